#!/usr/bin/python3
"""Peer of bench_pores edt: scipy.ndimage.distance_transform_edt on the same solid mask.

    /usr/bin/time -v /usr/bin/python3 bench/peer_scipy_edt.py MASK.bin M
        times scipy's exact Euclidean distance transform of the void (mask == 0); the peak
        memory is /usr/bin/time's "Maximum resident set size". scipy's transform is not
        periodic: the box faces are not boundaries, so voxels near a face see no solid across it.
    /usr/bin/python3 bench/peer_scipy_edt.py MASK.bin M --check DISTANCES.bin
        also compares with bench_pores' periodic squared distances (M^3 uint32): they must never
        exceed scipy's, and must equal them wherever scipy's distance is no larger than the
        distance to the nearest face (no periodic image can then be nearer).

MASK.bin: M^3 uint8, index (i*M + j)*M + k, 1 = solid, as written by bench_pores --write-mask.
"""
import sys
import time

import numpy as np
from scipy import ndimage


def main():
    if len(sys.argv) not in (3, 5) or (len(sys.argv) == 5 and sys.argv[3] != "--check"):
        sys.exit(__doc__)
    m = int(sys.argv[2])
    void = np.fromfile(sys.argv[1], dtype=np.uint8).reshape(m, m, m) == 0
    start = time.perf_counter()
    distance = ndimage.distance_transform_edt(void)
    seconds = time.perf_counter() - start
    print(f"scipy {__import__('scipy').__version__} distance_transform_edt M = {m}: "
          f"{seconds:.2f} s, max = {distance.max():.4f} voxels (not periodic)")
    if len(sys.argv) == 5:
        ours = np.fromfile(sys.argv[4], dtype=np.uint32).reshape(m, m, m)
        scipy_squared = np.rint(distance * distance).astype(np.int64)
        del distance
        index = np.arange(m)
        face = np.minimum(index + 1, m - index).astype(np.int64)
        to_face = np.minimum(np.minimum(face[:, None, None], face[None, :, None]),
                             face[None, None, :])
        interior = scipy_squared <= to_face * to_face
        longer = int(np.count_nonzero(ours > scipy_squared))
        differ = int(np.count_nonzero((ours != scipy_squared) & interior))
        print(f"check: {longer} voxels where the periodic distance exceeds scipy's (must be 0); "
              f"{differ} of {int(np.count_nonzero(interior))} voxels unaffected by the faces "
              f"differ (must be 0); {int(np.count_nonzero(ours < scipy_squared))} voxels are "
              f"nearer a solid through the periodic boundary")
        if longer or differ:
            sys.exit(1)


if __name__ == "__main__":
    main()
