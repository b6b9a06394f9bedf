// progress.h — progress reporting for long renders: a redrawn bar on a terminal, a plain line
// per 10 % step in logs, so neither a person nor a CI log waits in silence.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <mutex>
#include <string>

namespace vkpt {

// Counts work done out of a known total (pixels, samples) from any number of threads.
//
// On a terminal the line "label [#####.....]  42% 1234/4096, 3.2 s elapsed, ETA 4.1 s" is
// redrawn in place at most ten times a second. Elsewhere (a CI log, a file) one plain line is
// printed per 10 % step: "label: 40% (1640/4096), 3.2 s elapsed, ETA 4.8 s". finish() prints
// the final line. advance() is an atomic add and a clock read in the common case; call it per
// row or per batch rather than per sample.
class ProgressBar {
public:
    // Reports on stderr, as a bar when stderr is a terminal.
    ProgressBar(std::string label, std::uint64_t total);
    // Reports on out; isTerminal chooses the redrawn bar over the plain 10 % lines (tests).
    ProgressBar(std::string label, std::uint64_t total, std::ostream& out, bool isTerminal);
    // Counts without printing anything.
    static std::unique_ptr<ProgressBar> silent(std::string label, std::uint64_t total);
    // Ends an unfinished bar's line, so that an error printed next starts on its own line.
    ~ProgressBar();

    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void advance(std::uint64_t amount = 1);
    // An extra field shown after the figures, e.g. "active pixels 1234"; empty for none.
    void setStatus(std::string status);
    // Prints the final line (once); later calls do nothing.
    void finish();

    std::uint64_t done() const { return done_.load(std::memory_order_relaxed); }
    std::uint64_t total() const { return total_; }

private:
    using Clock = std::chrono::steady_clock;

    void redrawIfDue();
    void printIfNewStep(std::uint64_t doneNow);
    std::string figures(std::uint64_t doneNow, bool withEta) const;
    std::string barLine(std::uint64_t doneNow, bool withEta) const;
    double elapsedSeconds() const;
    std::int64_t elapsedNanoseconds() const;

    std::string label_;
    std::uint64_t total_;
    std::ostream* out_; // null: silent
    bool isTerminal_;
    Clock::time_point start_;

    std::atomic<std::uint64_t> done_{0};
    std::atomic<std::int64_t> nextRedrawNs_{0}; // terminal: earliest time of the next redraw
    std::atomic<int> lastStep_{0};              // log: last 10 % step printed (0..9)

    mutable std::mutex mutex_; // guards the stream, status_ and finished_
    std::string status_;
    bool finished_ = false;
    bool drawn_ = false;
};

// "4.2 s", "3 min 07 s", "2 h 05 min"; "?" for a negative or non-finite duration.
std::string formatDuration(double seconds);

// A bar on stderr, or, when quiet, one that counts but prints nothing (--quiet).
std::unique_ptr<ProgressBar> makeProgressBar(std::string label, std::uint64_t total, bool quiet);

} // namespace vkpt
