#include <poundfe/base/interruption.h>
#include <poundfe/base/interruption_hook.h>
#include <poundfe/base/interruption_scope.h>

#include <atomic>
#include <csignal>

namespace poundfe
{
  namespace
  {
    constexpr int signals[] = {SIGINT, SIGTERM};

    /// The first signal that arrived, 0: none.
    volatile std::sig_atomic_t received = 0;
    /// Whether the handler is installed for signals[i].
    bool installed[2] = {false, false};
    /// set_stop_at_safe_points
    bool stop_at_safe_points = false;
    /// request_stop: a stop without a signal
    volatile std::sig_atomic_t stop_requested = 0;
    /// set_interruption_hook (a lock-free atomic: read in the handler)
    std::atomic<void (*)()> hook{nullptr};
    static_assert(std::atomic<void (*)()>::is_always_lock_free);

    extern "C" void
    on_signal(const int signal)
    {
      received = signal;
      // Only sigaction here (async-signal-safe): the next signal of either
      // kind takes the default action, so a user can still kill.
      struct sigaction action = {};
      action.sa_handler       = SIG_DFL;
      sigemptyset(&action.sa_mask);
      for (int i = 0; i < 2; ++i)
        if (installed[i])
          sigaction(signals[i], &action, nullptr);
      if (void (*const call)() = hook.load())
        call();
    }
  } // namespace

  void
  set_interruption_hook(void (*const call)())
  {
    hook.store(call);
  }

  void
  install_interruption_handlers()
  {
    // Again after MPI_Init (PETSc's initialisation installs its own
    // handlers), unless a signal has come. Installed also where the signal
    // was ignored at start: a shell without job control starts background
    // jobs with SIGINT ignored, and `kill -INT` should stop them as it
    // stops a job in the foreground (at a safe point, files finished).
    if (received != 0)
      return;
    for (int i = 0; i < 2; ++i)
      {
        struct sigaction action = {};
        action.sa_handler       = on_signal;
        // the other signal waits while the handler runs
        sigemptyset(&action.sa_mask);
        for (const int s : signals)
          sigaddset(&action.sa_mask, s);
        // the I/O under way when it arrives simply continues
        action.sa_flags = SA_RESTART;
        installed[i]    = sigaction(signals[i], &action, nullptr) == 0;
      }
  }

  bool
  interruption_requested()
  {
    return received != 0 || stop_requested != 0;
  }

  void
  request_stop(const bool stop)
  {
    stop_requested = stop ? 1 : 0;
  }

  void
  set_stop_at_safe_points(const bool stop)
  {
    stop_at_safe_points = stop;
  }

  void
  throw_if_interrupted()
  {
    if (stop_at_safe_points && received != 0)
      throw Interrupted();
  }

  namespace
  {
    /// The handlers an InterruptionScope replaced (one scope at a time:
    /// Python runs one command at a time).
    struct sigaction saved_actions[2];
  } // namespace

  InterruptionScope::InterruptionScope()
  {
    for (int i = 0; i < 2; ++i)
      sigaction(signals[i], nullptr, &saved_actions[i]);
    received = 0;
    install_interruption_handlers();
  }

  InterruptionScope::~InterruptionScope()
  {
    for (int i = 0; i < 2; ++i)
      {
        sigaction(signals[i], &saved_actions[i], nullptr);
        installed[i] = false;
      }
    received = 0;
  }

  int
  InterruptionScope::signal() const
  {
    return received;
  }

  int
  interrupted_exit_status()
  {
    return 128 + (received != 0 ? static_cast<int>(received) : SIGINT);
  }
} // namespace poundfe
