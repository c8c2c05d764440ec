"""Helpers shared by the pvbatch tests: rank facts, agreement across ranks,
and plain numpy checks that do not rely on the plugin's own code."""
import os
import sys
import traceback

from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonCore import vtkIntArray

# Set by CTest's ENVIRONMENT; a script may override them from its command
# line with use_arguments().
PLUGIN = os.environ.get("PTM_PLUGIN", "")
DATA = os.environ.get("PTM_DATA", "")
OUTPUT = os.environ.get("PTM_OUTPUT", ".")


def use_arguments(argv):
    """Reads `<plugin path> <data dir> [expected ranks]` from a test's
    command line; returns the expected number of ranks (or None)."""
    global PLUGIN, DATA
    if len(argv) < 2:
        raise SystemExit("usage: pvbatch SCRIPT.py PLUGIN_PATH DATA_DIR [RANKS]")
    PLUGIN, DATA = argv[0], argv[1]
    return int(argv[2]) if len(argv) > 2 else None


def controller():
    return vtkMultiProcessController.GetGlobalController()


def rank():
    c = controller()
    return c.GetLocalProcessId() if c else 0


def size():
    c = controller()
    return c.GetNumberOfProcesses() if c else 1


def all_ranks_true(ok):
    """True on every rank if ok is true on every rank (collective)."""
    c = controller()
    if c is None or c.GetNumberOfProcesses() == 1:
        return bool(ok)
    send, receive = vtkIntArray(), vtkIntArray()
    send.InsertNextValue(1 if ok else 0)
    c.AllReduce(send, receive, 1)  # 1 = MIN_OP
    return receive.GetValue(0) == 1


def all_ranks_sum(value):
    """Sum of an integer over all ranks (collective)."""
    c = controller()
    if c is None or c.GetNumberOfProcesses() == 1:
        return int(value)
    send, receive = vtkIntArray(), vtkIntArray()
    send.InsertNextValue(int(value))
    c.AllReduce(send, receive, 2)  # 2 = SUM_OP
    return receive.GetValue(0)


def barrier():
    c = controller()
    if c is not None and c.GetNumberOfProcesses() > 1:
        c.Barrier()


def load_plugin(ns=None):
    """Loads the plugin on this process (every rank in --symmetric mode).
    Without ns the new proxies become functions of paraview.simple itself;
    with ns=globals() they are defined in the calling script."""
    from paraview import simple
    if not os.path.isfile(PLUGIN):
        raise RuntimeError("plugin not found: %r" % PLUGIN)
    simple.LoadPlugin(PLUGIN, remote=False, ns=ns)


def run_checks(main):
    """Runs main() on every rank. A rank that fails prints why and exits at
    once with status 1: mpiexec then ends the other ranks, which may be
    waiting in a collective the failed rank will never reach (agreeing on
    the failure with a collective could deadlock)."""
    try:
        main()
    except BaseException:
        traceback.print_exc()
        print("rank %d of %d: FAILED" % (rank(), size()))
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(1)
    barrier()
    print("rank %d of %d: passed" % (rank(), size()))
    sys.stdout.flush()


class ErrorCatcher:
    """Collects the messages of ErrorEvents (and, with warnings=True, of
    WarningEvents) of a VTK object."""

    def __init__(self, vtk_object, warnings=False):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.vtkCommonCore import VTK_STRING

        self.messages = []
        self.errors = []

        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            self.messages.append(str(message))
            self.errors.append(str(message))

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, message):
            self.messages.append(str(message))

        self._callbacks = (on_error, on_warning)  # keep them alive
        vtk_object.AddObserver("ErrorEvent", on_error)
        if warnings:
            vtk_object.AddObserver("WarningEvent", on_warning)

    @property
    def text(self):
        return "\n".join(self.messages)

    @property
    def errors_text(self):
        return "\n".join(self.errors)
