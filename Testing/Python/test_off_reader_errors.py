"""A malformed OFF file gives, on every rank and without hanging, an error
naming the file and the problem (reported by rank 0, which reads) and an
empty output; the same reader then reads a good file.

    mpiexec -n N pvbatch --symmetric test_off_reader_errors.py PLUGIN DATA_DIR N
"""
import os
import sys

import ptm_testing as t
from paraview import simple

CASES = {
    "truncated.off": ("OFF\n8 6 12\n0 0 0\n1 0 0\n", "expected 8 vertices but the file ends after 2"),
    "wrong_counts.off": ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n",
                         "line 7: unexpected data after the last face"),
    "bad_index.off": ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
                      "line 6: face 0 refers to vertex 9, but there are only 3 vertices"),
    "nan.off": ("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "line 4: vertex 1 has a NaN coordinate"),
    "text.off": ("OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
                 "line 4: vertex 1 has a non-numeric coordinate 'zero'"),
    "empty.off": ("", "the file is empty"),
    "missing.off": (None, "cannot open the file"),
}


def main():
    expected_ranks = t.use_arguments(sys.argv[1:])
    assert t.size() == expected_ranks, "%d ranks, expected %s" % (t.size(), expected_ranks)
    t.load_plugin()
    directory = os.path.join(t.OUTPUT, "off_errors_np%d" % t.size())
    if t.rank() == 0:
        os.makedirs(directory, exist_ok=True)
        for name, (text, _) in CASES.items():
            path = os.path.join(directory, name)
            if text is None:
                if os.path.exists(path):
                    os.remove(path)
            else:
                with open(path, "w") as f:
                    f.write(text)
    t.barrier()

    reader = simple.OFFSurfaceReader()
    catcher = t.ErrorCatcher(reader.GetClientSideObject())
    for name, (_, expected) in CASES.items():
        path = os.path.join(directory, name)
        catcher.messages.clear()
        reader.FileName = path
        reader.UpdatePipeline()
        local = reader.GetClientSideObject().GetOutputDataObject(0)
        assert (local.GetNumberOfPoints(), local.GetNumberOfCells()) == (0, 0), \
            "%s: rank %d output is not empty" % (name, t.rank())
        assert t.all_ranks_sum(local.GetNumberOfPoints() + local.GetNumberOfCells()) == 0, name
        if t.rank() == 0:
            assert (path + ": ") in catcher.text, "%s: error does not name the file: %r" % (name, catcher.text)
            assert expected in catcher.text, "%s: error does not say %r: %r" % (name, expected, catcher.text)
        else:
            assert catcher.text == "", "rank %d reported %r" % (t.rank(), catcher.text)

    # the reader factory hands even a malformed *.off to this reader, so the
    # user sees its message rather than "no reader found"
    broken = simple.OpenDataFile(os.path.join(directory, "text.off"))
    assert broken is not None and broken.GetXMLName() == "OFFSurfaceReader"
    simple.Delete(broken)

    # after the errors, the same reader reads a good file
    catcher.messages.clear()
    reader.FileName = os.path.join(t.DATA, "cube.off")
    reader.UpdatePipeline()
    local = reader.GetClientSideObject().GetOutputDataObject(0)
    assert catcher.text == "", catcher.text
    assert (t.all_ranks_sum(local.GetNumberOfPoints()), t.all_ranks_sum(local.GetNumberOfCells())) == (8, 12)


t.run_checks(main)
