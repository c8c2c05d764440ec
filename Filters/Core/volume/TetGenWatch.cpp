#include "TetGenWatch.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace ptm
{
namespace
{
// How often the phases and the processor time are looked at while a watch
// is on: a stall is caught within this much wall time of its limit.
constexpr int kWatchMilliseconds = 20;

// The processor time (user + system) process `pid` has used, from
// /proc/PID/stat; negative if it cannot be read.
double processorSeconds(pid_t pid)
{
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // the name in parentheses may hold spaces: the fields follow the last ')'
  const std::size_t close = text.rfind(')');
  if (close == std::string::npos)
  {
    return -1.0;
  }
  std::istringstream fields(text.substr(close + 1));
  std::string field;
  double user = -1, system = -1;
  // fields 3 (state) .. 15 (stime); utime is field 14
  for (int k = 3; k <= 15 && fields >> field; ++k)
  {
    if (k == 14)
    {
      user = std::atof(field.c_str());
    }
    else if (k == 15)
    {
      system = std::atof(field.c_str());
    }
  }
  const long ticks = ::sysconf(_SC_CLK_TCK);
  return user < 0 || system < 0 || ticks <= 0 ? -1.0 : (user + system) / static_cast<double>(ticks);
}

// Follows one run's phases and processor time; true once it counts as
// stalled in boundary recovery (RecoveryWatch).
class RecoveryTimer
{
public:
  RecoveryTimer(pid_t pid, std::FILE* phases, const RecoveryWatch& watch)
    : Pid(pid)
    , Phases(phases)
    , Watch(watch)
  {
  }
  // whether there is anything to watch (a watch asked for, phases to read)
  bool On() const { return this->Watch.active && this->Phases; }
  bool Stalled()
  {
    if (!this->On() || this->Done)
    {
      return false;
    }
    const TetGenPhase phase = tetgenPhase(this->Phases);
    const double used = processorSeconds(this->Pid);
    if (phase == TetGenPhase::AfterRecovery || used < 0)
    {
      this->Done = true; // past recovery, or nothing to measure by
      return false;
    }
    if (phase == TetGenPhase::BeforeRecovery)
    {
      return false;
    }
    if (this->Start < 0)
    {
      this->Start = used; // the first look in recovery: what came before
      return false;
    }
    const double limit = std::max(this->Watch.floorSeconds, this->Watch.factor * this->Start);
    return used - this->Start > limit;
  }

private:
  pid_t Pid;
  std::FILE* Phases;
  RecoveryWatch Watch;
  double Start = -1.0; // processor seconds when recovery was first seen
  bool Done = false;
};
} // namespace

TetGenPhase tetgenPhase(std::FILE* phases)
{
  if (!phases)
  {
    return TetGenPhase::BeforeRecovery;
  }
  std::string text;
  char buffer[4096];
  const int fd = ::fileno(phases);
  off_t at = 0;
  for (ssize_t got; (got = ::pread(fd, buffer, sizeof(buffer), at)) > 0; at += got)
  {
    text.append(buffer, static_cast<std::size_t>(got));
  }
  if (text.find("Removing exterior tetrahedra") != std::string::npos)
  {
    return TetGenPhase::AfterRecovery;
  }
  return text.find("Recovering boundaries") != std::string::npos ? TetGenPhase::InRecovery
                                                                : TetGenPhase::BeforeRecovery;
}

TetGenWait waitForTetGen(const TetGenProcess& process, std::FILE* phases, double wallSeconds,
  const RecoveryWatch& watch)
{
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wallSeconds);
  RecoveryTimer recovery(process.pid, phases, watch);
  for (;;)
  {
    const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0)
    {
      return TetGenWait::WallLimit;
    }
    const int wait = recovery.On() ? kWatchMilliseconds : static_cast<int>(std::min(left * 1000.0 + 1.0, 60000.0));
    pollfd p{ process.fd, POLLIN, 0 };
    const int r = ::poll(&p, 1, wait);
    if (r > 0 || (r < 0 && errno != EINTR))
    {
      return TetGenWait::Ready; // data, end of file or an error: the read tells which
    }
    if (recovery.Stalled())
    {
      return TetGenWait::StalledInRecovery;
    }
  }
}
} // namespace ptm
