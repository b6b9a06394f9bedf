// phase_log.h — where a process's time goes: named phases (load, BVH build, pipelines, render,
// write, …), each with its wall and CPU seconds, nested where one phase is part of another.
// One log per process, since the phases are the process's: the programs' report prints it and
// writes it to the statistics JSON (render_report.h).
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace vkpt {

struct PhaseTime {
    std::string name;
    std::uint32_t depth = 0; // 0: a phase of the process; 1: part of the phase before it, …
    double wallSeconds = 0.0;
    double cpuSeconds = 0.0; // the whole process's, every thread (a CPU device's workers too)
};

class PhaseLog {
public:
    // Phases in the order they began; a nested phase follows its parent.
    std::vector<PhaseTime> phases() const;
    // Wall seconds since the log was made: the first use in the process.
    double secondsSinceStart() const;
    void clear();

private:
    friend class ScopedPhase;
    std::size_t begin(const std::string& name);
    void end(std::size_t index, double wallSeconds, double cpuSeconds);

    mutable std::mutex mutex_;
    std::vector<PhaseTime> phases_;
    std::uint32_t open_ = 0; // phases begun and not yet ended: the next one's depth
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The process's log.
PhaseLog& processPhases();

// Process CPU seconds so far, every thread.
double processCpuSeconds();

// Times a phase from construction to destruction (or to end()) into the process's log.
class ScopedPhase {
public:
    explicit ScopedPhase(const std::string& name, PhaseLog& log = processPhases());
    ~ScopedPhase() { end(); }
    ScopedPhase(const ScopedPhase&) = delete;
    ScopedPhase& operator=(const ScopedPhase&) = delete;
    void end();

private:
    PhaseLog& log_;
    std::size_t index_;
    std::chrono::steady_clock::time_point wallStart_;
    double cpuStart_;
    bool ended_ = false;
};

// "load 0.02 s, prepare 0.31 s (BVH build 0.22 s, BVH collapse 0.05 s), …" of top-level phases
// with their direct parts, for the summary line.
std::string describePhases(const std::vector<PhaseTime>& phases);

} // namespace vkpt
