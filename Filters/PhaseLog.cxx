#include "PhaseLog.h"

#include "vtkMultiProcessController.h"

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace ptm::phases
{
namespace
{
// of this process and of the children it waited for: the mesher runs
// TetGen in processes of its own (TetGenProcess.h)
double processorSeconds()
{
  double seconds = 0;
  for (int who : { RUSAGE_SELF, RUSAGE_CHILDREN })
  {
    rusage usage{};
    getrusage(who, &usage);
    seconds += static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
      1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }
  return seconds;
}

// The open log of this process; its destructor writes the line of the end.
class Log
{
public:
  ~Log()
  {
    if (this->File)
    {
      std::fprintf(this->File, "%ld\tend\t%.6f\t0\tend\n", this->Lines, processorSeconds());
      std::fclose(this->File);
    }
  }

  void write(vtkMultiProcessController* controller, const char* kind, std::size_t bytes)
  {
    if (!this->Opened)
    {
      this->open(controller);
    }
    if (this->File)
    {
      std::fprintf(this->File, "%ld\t%s\t%.6f\t%zu\t%s\n", this->Lines++, this->Phase.c_str(),
        processorSeconds(), bytes, kind);
      std::fflush(this->File);
    }
  }

  std::string Phase = "start";

private:
  void open(vtkMultiProcessController* controller)
  {
    this->Opened = true;
    const char* dir = std::getenv("PTM_PHASE_LOG");
    if (!dir || !*dir)
    {
      return;
    }
    const int rank = controller ? controller->GetLocalProcessId() : 0;
    const std::string path = std::string(dir) + "/rank-" + std::to_string(rank) + ".tsv";
    this->File = std::fopen(path.c_str(), "w");
  }

  bool Opened = false;
  std::FILE* File = nullptr;
  long Lines = 0;
};

Log& theLog()
{
  static Log log;
  return log;
}
} // namespace

void setPhase(vtkMultiProcessController* controller, const char* name)
{
  // the line ends the phase before (every rank runs every filter, in order)
  theLog().write(controller, "phase", 0);
  theLog().Phase = name;
}

void collective(vtkMultiProcessController* controller, const char* kind, std::size_t bytes)
{
  theLog().write(controller, kind, bytes);
}
} // namespace ptm::phases
