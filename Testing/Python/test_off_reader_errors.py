"""A malformed OFF file gives an error naming the file and the problem, and
an empty output, on every rank, without hanging."""
import os

import ptm_testing as t
from paraview import simple

CASES = {
    "truncated.off": ("OFF\n8 6 12\n0 0 0\n1 0 0\n", "expected 8 vertices but the file ends after 2"),
    "bad_index.off": ("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n", "refers to vertex 9"),
    "nan.off": ("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "NaN"),
    "text.off": ("OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "non-numeric coordinate 'zero'"),
    "empty.off": ("", "the file is empty"),
}


def main():
    t.load_plugin()
    directory = os.path.join(t.OUTPUT, "off_errors_np%d" % t.size())
    if t.rank() == 0:
        os.makedirs(directory, exist_ok=True)
        for name, (text, _) in CASES.items():
            with open(os.path.join(directory, name), "w") as f:
                f.write(text)
    t.barrier()
    for name, (_, expected) in CASES.items():
        path = os.path.join(directory, name)
        reader = simple.OFFSurfaceReader(FileName=path)
        catcher = t.ErrorCatcher(reader.GetClientSideObject())
        reader.UpdatePipeline()
        local = reader.GetClientSideObject().GetOutputDataObject(0)
        assert local.GetNumberOfPoints() == 0 and local.GetNumberOfCells() == 0, name
        if t.rank() == 0:
            assert path in catcher.text, "error does not name the file: %r" % catcher.text
            assert expected in catcher.text, "error does not say %r: %r" % (expected, catcher.text)
        simple.Delete(reader)


t.run_checks(main)
