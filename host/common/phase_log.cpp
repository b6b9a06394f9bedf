// phase_log.cpp — the log is filled from one thread at a time in practice; the mutex keeps it
// safe should a phase end on a worker (pipelines created while the host works).
#include "common/phase_log.h"

#include <cstdio>

#include <time.h>

namespace vkpt {

std::vector<PhaseTime> PhaseLog::phases() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return phases_;
}

double PhaseLog::secondsSinceStart() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void PhaseLog::clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    phases_.clear();
    open_ = 0;
}

std::size_t PhaseLog::begin(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    phases_.push_back({name, open_, 0.0, 0.0});
    ++open_;
    return phases_.size() - 1;
}

void PhaseLog::end(std::size_t index, double wallSeconds, double cpuSeconds) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (open_ > 0) --open_;
    if (index >= phases_.size()) return; // cleared meanwhile
    phases_[index].wallSeconds = wallSeconds;
    phases_[index].cpuSeconds = cpuSeconds;
}

PhaseLog& processPhases() {
    static PhaseLog log;
    return log;
}

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

ScopedPhase::ScopedPhase(const std::string& name, PhaseLog& log)
    : log_(log), index_(log.begin(name)), wallStart_(std::chrono::steady_clock::now()),
      cpuStart_(processCpuSeconds()) {}

void ScopedPhase::end() {
    if (ended_) return;
    ended_ = true;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart_).count();
    log_.end(index_, wall, processCpuSeconds() - cpuStart_);
}

namespace {

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2f s", value);
    return text;
}

} // namespace

std::string describePhases(const std::vector<PhaseTime>& phases) {
    std::string text;
    for (std::size_t i = 0; i < phases.size(); ++i) {
        if (phases[i].depth != 0) continue;
        if (!text.empty()) text += ", ";
        text += phases[i].name + " " + seconds(phases[i].wallSeconds);
        std::string parts;
        for (std::size_t j = i + 1; j < phases.size() && phases[j].depth > 0; ++j) {
            if (phases[j].depth != 1) continue;
            if (!parts.empty()) parts += ", ";
            parts += phases[j].name + " " + seconds(phases[j].wallSeconds);
        }
        if (!parts.empty()) text += " (" + parts + ")";
    }
    return text;
}

} // namespace vkpt
