#include "harness/run/parallel_run.h"

namespace cyclecert {

int defaultJobs() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

}  // namespace cyclecert
