#pragma once
// --jobs N for `check` and `fuzz`: items 0, 1, 2, … (cases, or batches of cases) are worked on by N
// threads, and their results committed — counted, written to results.jsonl, printed — one at a
// time and in item order, so a run with --jobs N writes what --jobs 1 writes, in the same order,
// and the results file keeps one writer and whole lines.
//
// Threads, not processes: each worker owns its engine (an in-process engine object, one child
// process, or one rs274 per worker); the shared code is free of mutable static state — the
// reference's parse cache is thread_local, the oracles are const, RapidCheck's generators run with
// an explicit rc::Random (its ImplicitParam stack, which is not thread-safe, is only used by
// `*gen` inside properties, which the case generators do not use), and the subprocess code makes
// its pipes close-on-exec and blocks SIGPIPE per thread.
#include <algorithm>
#include <condition_variable>
#include <exception>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace cyclecert {

// The default of --jobs: the number of cores, at least 1.
int defaultJobs();

// Runs produce(worker, item) for items 0, 1, 2, … on `jobs` workers (worker 0 is the calling
// thread; with jobs = 1 no thread is started) and commit(worker, result) for each result in item
// order, never two at once. produce returns nothing when there are no more items (that item and the
// later ones are not committed); commit returns false to stop the run (later items are not
// committed). At most a few items per worker are worked on ahead of the next commit. An exception
// a produce throws stops the run when its item's turn to be committed comes (the items before it
// are committed, as with one worker), one a commit throws at once; it is rethrown here once every
// worker is done.
template <class Result>
void runInItemOrder(int jobs, const std::function<std::optional<Result>(int worker, long item)>& produce,
                    const std::function<bool(int worker, Result& result)>& commit) {
  jobs = std::max(jobs, 1);
  const long window = 4L * jobs;  // items worked on ahead of the next commit, at most
  std::mutex m;
  std::condition_variable roomAhead;
  long nextItem = 0, nextCommit = 0, end = -1;  // end: the first item that produced nothing, once known
  bool stop = false, committing = false;
  struct Produced {
    std::optional<Result> result;
    std::exception_ptr thrown;
  };
  std::map<long, Produced> ready;
  std::exception_ptr failure;

  const auto fail = [&](std::exception_ptr e) {  // with m held
    if (!failure) failure = e;
    stop = true;
    roomAhead.notify_all();
  };
  // Commits the results that are next in order, unless another worker is committing (it will).
  const auto commitReady = [&](int worker, std::unique_lock<std::mutex>& lock) {
    if (committing) return;
    committing = true;
    for (auto it = ready.find(nextCommit); !stop && it != ready.end(); it = ready.find(nextCommit)) {
      Produced produced = std::move(it->second);
      ready.erase(it);
      if (produced.thrown) {
        fail(produced.thrown);
        break;
      }
      std::optional<Result>& result = produced.result;
      if (!result) {
        stop = true;
        break;
      }
      lock.unlock();
      bool go = false;
      std::exception_ptr thrown;
      try {
        go = commit(worker, *result);
      } catch (...) {
        thrown = std::current_exception();
      }
      lock.lock();
      ++nextCommit;
      if (thrown) fail(thrown);
      else if (!go) stop = true;
      roomAhead.notify_all();
    }
    committing = false;
    roomAhead.notify_all();
  };
  const auto work = [&](int worker) {
    std::unique_lock<std::mutex> lock(m);
    for (;;) {
      roomAhead.wait(lock, [&] { return stop || nextItem - nextCommit < window; });
      if (stop || (end >= 0 && nextItem >= end)) break;
      const long item = nextItem++;
      lock.unlock();
      Produced produced;
      try {
        produced.result = produce(worker, item);
      } catch (...) {
        produced.thrown = std::current_exception();
      }
      lock.lock();
      if (!produced.result) end = end < 0 ? item : std::min(end, item);  // no later item is drawn
      ready.emplace(item, std::move(produced));
      commitReady(worker, lock);
    }
    roomAhead.notify_all();
  };

  std::vector<std::thread> threads;
  for (int w = 1; w < jobs; ++w) threads.emplace_back(work, w);
  work(0);
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace cyclecert
