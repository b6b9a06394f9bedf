// interrupt.cpp — the signal handlers only store to lock-free atomics (async-signal-safe).
#include "app/interrupt.h"

#include <csignal>

namespace vkpt {

namespace {

std::atomic<bool> requested{false};
std::atomic<int> stopSignal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "set from a signal handler");

extern "C" void onStopSignal(int signal) {
    int none = 0;
    stopSignal.compare_exchange_strong(none, signal);
    requested.store(true);
}

} // namespace

const std::atomic<bool>& stopRequested() {
    return requested;
}

void installStopHandlers() {
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int exitCodeForStop() {
    const int signal = stopSignal.load();
    return signal ? 128 + signal : 0;
}

} // namespace vkpt
