// SPDX-License-Identifier: GPL-3.0-or-later
/// @file convert.cpp
/// @brief Array-likes to contiguous float64 with the checks of convert.hpp, and string columns.
#include "convert.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <exception>
#include <mutex>
#include <thread>

#include "dfchaos/errors.hpp"
#include "dfchaos/stop.hpp"
#include "kit/budget.hpp"

namespace dfchaos::python {

namespace {
/// A non-finite value as Python spells it ('nan', 'inf', '-inf'), as the CLI quotes its text.
std::string spell(double x) { return std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf"); }
}  // namespace

double finite(const char* name, double x) {
  if (!std::isfinite(x)) throw InvalidParameter(name, "must be a finite number (got '" + spell(x) + "')");
  return x;
}

Reals as_reals(const py::handle& obj, const char* name) {
  py::array any = py::array::ensure(obj);
  if (!any) throw py::type_error(std::string(name) + ": expected a real number or an array-like of real numbers");
  const char kind = any.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + ": expected real numbers, got an array of dtype " + py::str(any.dtype()).cast<std::string>());
  const py::ssize_t n = any.size();  // checked before the copy (a broadcast view can be huge)
  if (n > kMaxElements)
    throw InvalidParameter(name, "number of elements <= " + format_shortest(static_cast<double>(kMaxElements)), static_cast<double>(n));
  Reals r;
  r.array = RealArray::ensure(any);
  if (!r.array) throw py::type_error(std::string(name) + ": cannot be converted to float64");
  r.scalar = r.array.ndim() == 0;
  const double* x = r.array.data();
  for (py::ssize_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) {
      if (r.scalar) finite(name, x[i]);
      throw InvalidParameter(name, "must be a finite number (got '" + spell(x[i]) + "' at flat index " + std::to_string(i) + ")");
    }
  return r;
}

void require_constructed(py::handle obj) {
  if (!obj || obj.is_none()) return;
  const py::detail::type_info* type = py::detail::get_type_info(typeid(Parameters));
  if (type == nullptr || PyObject_TypeCheck(obj.ptr(), type->type) == 0) return;
  auto* instance = reinterpret_cast<py::detail::instance*>(obj.ptr());
  if (!instance->get_value_and_holder(type).holder_constructed())
    throw py::type_error(
        "dfchaos.Parameters: this object was never initialised (made by Parameters.__new__ without __init__); "
        "build it as dfchaos.Parameters(a, b, q)");
}

CallBudget call_budget(double max_seconds, double max_memory) {
  const kit::ProcessBudget b = kit::parse_budget(format_double(finite("max-seconds", max_seconds)), format_double(finite("max-memory", max_memory)));
  return CallBudget{b.seconds, b.gib};
}

namespace {

/// Resident memory of the process in bytes (/proc/self/statm), or -1 when it cannot be read.
double resident_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return -1;
  long pages = 0, resident = 0;
  const int got = std::fscanf(f, "%ld %ld", &pages, &resident);
  std::fclose(f);
  return got == 2 ? static_cast<double>(resident) * static_cast<double>(::sysconf(_SC_PAGESIZE)) : -1;
}

}  // namespace

namespace {

/// A thread that runs one job at a time and then waits for the next. Workers are kept for the life
/// of the process and reused: the thread-local state a call builds (the OpenMP thread pool of a
/// sweep, the caches of Arb and FLINT in that pool's threads) is built once per worker, not once
/// per call, and is never left behind by a thread that ends.
class Worker {
 public:
  Worker() : thread_([this] { loop(); }) { thread_.detach(); }
  /// Starts `job` on this worker (which must be idle).
  void start(std::function<void()> job) {
    const std::lock_guard<std::mutex> g(m_);
    job_ = std::move(job);
    cv_.notify_one();
  }

 private:
  void loop() {
    for (;;) {
      std::function<void()> job;
      {
        std::unique_lock<std::mutex> lock(m_);
        cv_.wait(lock, [&] { return static_cast<bool>(job_); });
        job = std::move(job_);
        job_ = nullptr;
      }
      job();  // never throws: run_interruptible's job catches everything
    }
  }
  std::mutex m_;
  std::condition_variable cv_;
  std::function<void()> job_;
  std::thread thread_;
};

/// The idle workers. One is taken per call and given back when the call is over; as many exist as
/// calls have run at once (one, unless several Python threads call the module together).
std::mutex g_idle_lock;
std::vector<Worker*> g_idle;

Worker* take_worker() {
  const std::lock_guard<std::mutex> g(g_idle_lock);
  if (g_idle.empty()) return new Worker();  // kept for the life of the process
  Worker* w = g_idle.back();
  g_idle.pop_back();
  return w;
}

void give_back(Worker* w) {
  const std::lock_guard<std::mutex> g(g_idle_lock);
  g_idle.push_back(w);
}

}  // namespace

void run_interruptible(const std::function<void()>& body, const CallBudget& budget) {
  using Clock = std::chrono::steady_clock;
  enum class Why { None, Signal, Time, Memory };
  StopToken token;
  std::exception_ptr error;
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  Why why = Why::None;
  {
    py::gil_scoped_release nogil;
    const double base = budget.gib > 0 ? resident_bytes() : -1;
    const double allowed = budget.gib * 1073741824.0;
    const Clock::time_point start = Clock::now();
    Worker* worker = take_worker();
    worker->start([&] {
      {
        const StopScope scope(&token);
        try {
          body();
        } catch (...) {
          error = std::current_exception();
        }
      }
      const std::lock_guard<std::mutex> g(m);
      done = true;
      cv.notify_one();
    });
    Clock::time_point next_signals = start + std::chrono::milliseconds(100);
    std::unique_lock<std::mutex> lock(m);
    while (!done) {
      cv.wait_for(lock, std::chrono::milliseconds(10));
      if (done || why != Why::None) continue;  // once asked to stop, only wait for the worker
      const Clock::time_point now = Clock::now();
      if (budget.seconds > 0 && std::chrono::duration<double>(now - start).count() >= budget.seconds) {
        why = Why::Time;
      } else if (base >= 0 && resident_bytes() - base > allowed) {
        why = Why::Memory;
      } else if (now >= next_signals) {
        next_signals = now + std::chrono::milliseconds(100);
        lock.unlock();
        bool interrupted = false;
        {
          py::gil_scoped_acquire gil;
          interrupted = PyErr_CheckSignals() != 0;  // the Python error (KeyboardInterrupt) stays set
        }
        lock.lock();
        if (interrupted) why = Why::Signal;
      }
      if (why != Why::None) token.request();
    }
    lock.unlock();
    // The job has set `done` under the lock as its last use of this frame: the worker is free.
    give_back(worker);
  }
  switch (why) {
    case Why::Signal: throw py::error_already_set();
    case Why::Time: throw GaveUp("gave up: the time budget of " + format_shortest(budget.seconds) + " s ran out (max_seconds raises it)");
    case Why::Memory: throw GaveUp("gave up: the memory budget of " + format_shortest(budget.gib) + " GiB ran out (max_memory raises it)");
    case Why::None: break;
  }
  if (error) std::rethrow_exception(error);
}

StrColumn::StrColumn(const std::vector<py::ssize_t>& shape, py::ssize_t width)
    : array(py::dtype("<U" + std::to_string(width)), shape), width_(width) {
  data_ = static_cast<char32_t*>(array.mutable_data());
  std::memset(static_cast<void*>(data_), 0, static_cast<std::size_t>(array.nbytes()));
}

}  // namespace dfchaos::python
