"""Every case of test_pipeline.py gives bit-identical results with 1 and 2
ranks: the same complex, relaxed points, mesh points and tetrahedra by
global id."""
import glob
import os
import sys

import numpy as np

first, second = sys.argv[1], sys.argv[2]
digests = sorted(glob.glob(os.path.join(first, "*_digest.npz")))
assert digests, "no results in %s" % first
failures = 0
for path in digests:
    other = os.path.join(second, os.path.basename(path))
    a, b = np.load(path), np.load(other)
    for key in a.files:
        same = a[key].shape == b[key].shape and np.array_equal(a[key].view(np.uint8), b[key].view(np.uint8))
        if not same:
            failures += 1
            print("DIFFERENT %s: %s" % (os.path.basename(path), key))
    print("compared %s" % os.path.basename(path))
print("%d differences" % failures)
sys.exit(1 if failures else 0)
