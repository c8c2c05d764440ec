// ptm-tetgen: the process one TetGen run happens in (TetGenProcess.h).
//
//   ptm-tetgen SOCKET PHASES
//
// SOCKET: the descriptor the request arrives on and the result goes back
// to; PHASES: the descriptor TetGen's phase lines go to, or -1. Started by
// the mesher only; by hand it has nothing to read.
#include "TetGenProcess.h"

#include <tetgen.h>

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv)
{
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: ptm-tetgen SOCKET PHASES (started by the ParallelTetMesher, not by hand)\n");
    return 2;
  }
  const int fd = std::atoi(argv[1]), phasesFd = std::atoi(argv[2]);
  tetgenio in, addin;
  ptm::TetGenRequest request;
  if (fd < 0 || !ptm::readTetGenRequest(fd, in, addin, request))
  {
    std::fprintf(stderr, "ptm-tetgen: the request on descriptor %s was cut short or malformed\n", argv[1]);
    return 1;
  }
  request.phases = phasesFd >= 0 ? ::fdopen(phasesFd, "w") : nullptr;
  ptm::runTetGenChild(request, fd);
}
