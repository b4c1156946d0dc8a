#include "app/figure_thread.h"

#include <condition_variable>
#include <deque>
#include <future>
#include <mutex>
#include <thread>

#include "core/vector_state.h"
#include "viz/vtk_render.h"

namespace rt::app {
namespace {

class FigureThread {
 public:
  FigureThread() : thread_([this] { loop(); }) {}

  // At the program's end: the thread ends, and its window with it, its context current there.
  ~FigureThread() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

  void run(const std::function<void()>& draw) {
    std::packaged_task<void()> task(draw);
    std::future<void> done = task.get_future();
    {
      const std::lock_guard lock(mutex_);
      tasks_.push_back(std::move(task));
    }
    wake_.notify_one();
    done.get();
  }

 private:
  void loop() {
    clearUpperVectorState();  // as every computation thread (core/vector_state.h)
    viz::keepOffscreenWindowsOnThisThread();
    for (;;) {
      std::packaged_task<void()> task;
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
        if (tasks_.empty()) return;
        task = std::move(tasks_.front());
        tasks_.pop_front();
      }
      task();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::packaged_task<void()>> tasks_;
  bool stopping_ = false;
  std::thread thread_;  // last: started once the members it uses are
};

}  // namespace

void onFigureThread(const std::function<void()>& draw) {
  static FigureThread thread;
  thread.run(draw);
}

}  // namespace rt::app
