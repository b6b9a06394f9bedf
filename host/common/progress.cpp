// progress.cpp — the progress bar of long renders: atomic counting, rate-limited redraws.
#include "common/progress.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <utility>

#include <unistd.h>

namespace vkpt {

namespace {

constexpr std::int64_t kRedrawIntervalNs = 100'000'000; // at most ten redraws a second
constexpr int kBarWidth = 24;
constexpr int kLogSteps = 10; // one log line per 10 %

// Fraction done in [0, 1]; an empty job counts as complete.
double fractionDone(std::uint64_t done, std::uint64_t total) {
    if (total == 0) return 1.0;
    return double(std::min(done, total)) / double(total);
}

// Whole percent, rounded down so that "100%" means every item is done. The division is exact
// whenever the true quotient is an integer, so step boundaries are not missed by rounding.
int percentDone(std::uint64_t done, std::uint64_t total) {
    if (total == 0) return 100;
    return int(std::floor(100.0 * double(std::min(done, total)) / double(total)));
}

int stepOf(std::uint64_t done, std::uint64_t total) {
    if (total == 0) return 0;
    return int(std::floor(kLogSteps * double(std::min(done, total)) / double(total)));
}

std::string countText(std::uint64_t done, std::uint64_t total) {
    return std::to_string(done) + "/" + std::to_string(total);
}

std::string etaText(double elapsed, std::uint64_t done, std::uint64_t total) {
    if (done == 0) return "?";
    const double remaining = double(total - std::min(done, total));
    return formatDuration(elapsed * remaining / double(done));
}

// Built by appending: GCC 12 at -O2 reports a false -Wrestrict for "[" + std::string(...).
std::string barGraphic(double fraction) {
    const auto filled = std::size_t(std::lround(std::clamp(fraction, 0.0, 1.0) * kBarWidth));
    std::string bar = "[";
    bar.append(filled, '#').append(std::size_t(kBarWidth) - filled, '.') += ']';
    return bar;
}

std::string printed(const char* format, int a, int b) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, a, b);
    return buffer;
}

std::string percentText(int percent) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%3d%%", percent);
    return buffer;
}

} // namespace

std::string formatDuration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) return "?";
    if (seconds >= 1000.0 * 3600.0) return "more than 1000 h"; // an early ETA can be absurd
    if (seconds < 60.0) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.1f s", seconds);
        return buffer;
    }
    const auto whole = std::int64_t(seconds);
    if (whole < 3600) return printed("%d min %02d s", int(whole / 60), int(whole % 60));
    return printed("%d h %02d min", int(whole / 3600), int(whole % 3600 / 60));
}

ProgressBar::ProgressBar(std::string label, std::uint64_t total)
    : ProgressBar(std::move(label), total, std::cerr, isatty(STDERR_FILENO) == 1) {}

ProgressBar::ProgressBar(std::string label, std::uint64_t total, std::ostream& out, bool isTerminal)
    : label_(std::move(label)), total_(total), out_(&out), isTerminal_(isTerminal),
      start_(Clock::now()) {}

ProgressBar::~ProgressBar() {
    std::lock_guard lock(mutex_);
    if (isTerminal_ && drawn_ && !finished_) *out_ << '\n' << std::flush;
}

void ProgressBar::advance(std::uint64_t amount) {
    const std::uint64_t doneNow = done_.fetch_add(amount, std::memory_order_relaxed) + amount;
    if (out_ == nullptr) return;
    if (isTerminal_)
        redrawIfDue();
    else
        printIfNewStep(doneNow);
}

void ProgressBar::setStatus(std::string status) {
    std::lock_guard lock(mutex_);
    status_ = std::move(status);
}

void ProgressBar::finish() {
    std::lock_guard lock(mutex_);
    if (finished_) return;
    finished_ = true;
    if (out_ == nullptr) return;
    const std::uint64_t doneNow = done();
    if (isTerminal_) {
        *out_ << barLine(doneNow, false) << '\n' << std::flush;
        return;
    }
    *out_ << label_ << ": done, " << countText(doneNow, total_) << " in "
          << formatDuration(elapsedSeconds()) << (status_.empty() ? "" : ", " + status_) << '\n'
          << std::flush;
}

// Workers must not queue behind a redraw, so whoever finds the stream busy just skips it.
void ProgressBar::redrawIfDue() {
    if (elapsedNanoseconds() < nextRedrawNs_.load(std::memory_order_relaxed)) return;
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || finished_) return;
    const std::int64_t now = elapsedNanoseconds();
    if (now < nextRedrawNs_.load(std::memory_order_relaxed)) return;
    nextRedrawNs_.store(now + kRedrawIntervalNs, std::memory_order_relaxed);
    *out_ << barLine(done(), true) << std::flush;
    drawn_ = true;
}

// The step is re-read under the lock so that lines come out in increasing order even when
// several threads cross step boundaries at once; 100 % is left to finish().
void ProgressBar::printIfNewStep(std::uint64_t doneNow) {
    const int step = std::min(stepOf(doneNow, total_), kLogSteps - 1);
    if (step <= lastStep_.load(std::memory_order_relaxed)) return;
    std::lock_guard lock(mutex_);
    const std::uint64_t latest = done();
    const int latestStep = std::min(stepOf(latest, total_), kLogSteps - 1);
    if (finished_ || latestStep <= lastStep_.load(std::memory_order_relaxed)) return;
    lastStep_.store(latestStep, std::memory_order_relaxed);
    *out_ << label_ << ": " << percentDone(latest, total_) << "% (" << countText(latest, total_)
          << "), " << figures(latest, true) << '\n'
          << std::flush;
}

// "3.2 s elapsed, ETA 4.1 s, active pixels 1234"; the caller holds the lock (status_).
std::string ProgressBar::figures(std::uint64_t doneNow, bool withEta) const {
    const double elapsed = elapsedSeconds();
    std::string text = formatDuration(elapsed) + " elapsed";
    if (withEta) text += ", ETA " + etaText(elapsed, doneNow, total_);
    if (!status_.empty()) text += ", " + status_;
    return text;
}

// Carriage return, the bar, and an erase-to-end-of-line so a shorter line leaves no tail.
std::string ProgressBar::barLine(std::uint64_t doneNow, bool withEta) const {
    return "\r" + label_ + " " + barGraphic(fractionDone(doneNow, total_)) + " " +
           percentText(percentDone(doneNow, total_)) + " " + countText(doneNow, total_) + ", " +
           figures(doneNow, withEta) + "\x1b[K";
}

double ProgressBar::elapsedSeconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

std::int64_t ProgressBar::elapsedNanoseconds() const {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start_).count();
}

std::unique_ptr<ProgressBar> ProgressBar::silent(std::string label, std::uint64_t total) {
    std::unique_ptr<ProgressBar> bar(new ProgressBar(std::move(label), total, std::cerr, false));
    bar->out_ = nullptr;
    return bar;
}

std::unique_ptr<ProgressBar> makeProgressBar(std::string label, std::uint64_t total, bool quiet) {
    if (quiet) return ProgressBar::silent(std::move(label), total);
    return std::make_unique<ProgressBar>(std::move(label), total);
}

} // namespace vkpt
