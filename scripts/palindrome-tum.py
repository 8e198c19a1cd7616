#!/usr/bin/env python3
"""A long TUM folder from a short one: its frames listed forwards, then backwards, and so on,
REPS passes in all, with time stamps that keep increasing (each backward pass is the forward one
mirrored in time). Colour and depth images are linked, not copied; the ground truth is mirrored
the same way. For long-run checks of the SLAM mode (memory, time per frame, loops) on real frames.

Usage: scripts/palindrome-tum.py SOURCE_FOLDER OUTPUT_FOLDER REPS
Keep the camera's name (fr1, fr3, ...) in OUTPUT_FOLDER's name: it chooses the intrinsics."""
import os
import sys


def rows(folder, name):
    out = []
    for line in open(os.path.join(folder, name)):
        if line.startswith('#') or not line.strip():
            continue
        parts = line.split()
        out.append((float(parts[0]), parts[1:]))
    return out


def passes(entries, t0, t1, reps):
    span, result = t1 - t0, []
    for k in range(reps):
        if k % 2 == 0:
            seg = [(t + k * span, v) for t, v in entries]
        else:
            seg = [((k + 1) * span + 2 * t0 - t, v) for t, v in reversed(entries)]
        if result and seg and seg[0][0] <= result[-1][0] + 1e-4:
            seg = seg[1:]  # the turn's frame once
        result += seg
    return result


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    src, dst, reps = os.path.abspath(sys.argv[1]), sys.argv[2], int(sys.argv[3])
    os.makedirs(dst, exist_ok=True)
    for d in ('rgb', 'depth'):
        if not os.path.exists(os.path.join(dst, d)):
            os.symlink(os.path.join(src, d), os.path.join(dst, d))
    rgb, depth = rows(src, 'rgb.txt'), rows(src, 'depth.txt')
    t0, t1 = rgb[0][0] - 0.016, rgb[-1][0] + 0.016  # half a frame interval around the colour
    lists = {'rgb.txt': rgb, 'depth.txt': [r for r in depth if t0 <= r[0] <= t1]}
    if os.path.exists(os.path.join(src, 'groundtruth.txt')):
        lists['groundtruth.txt'] = [r for r in rows(src, 'groundtruth.txt') if t0 <= r[0] <= t1]
    for name, entries in lists.items():
        with open(os.path.join(dst, name), 'w') as f:
            for t, v in passes(entries, t0, t1, reps):
                f.write('%.6f %s\n' % (t, ' '.join(v)))
    print('%d frames in %s' % (len(passes(rgb, t0, t1, reps)), dst))


if __name__ == '__main__':
    main()
