#!/usr/bin/env python3
"""Path error of a robot job run on the UR simulator (docs/robot-cell.md, "Measured").

    robot_path_error.py TRACE.csv OUT CELL.json

TRACE.csv is the simulator's trace (`multidir simulate --ur MODEL --cell CELL --trace TRACE.csv`), OUT the folder
`multidir robot-program` wrote (its step-NN.script files), CELL the cell the job was converted for. For every tick
the simulated extruder ran in a step's program (filament speed above 0), the nozzle's point on the part (the
trace's nozzle_*_mm: the fixed tip in the platform frame) is measured against that step's extrusion moves: the
program's movel targets read through the cell, as the run tests read them (tests/app/cli_run_robot_test.cpp,
nozzleSegments). The search goes forward through the moves as the ticks do (the nearest of the move the last tick
was on and the next ones), so a tick is measured against the move it is printing, not a crossing one.
Prints per step: extruding ticks, the largest and the mean distance (mm). The programs' own targets reproduce the
G-code to 1e-7 mm (KittenRobotProgram.ReplayedNozzlePath...), so this is the path error against the G-code.
Also per step the simulated arm's time in its moves (movel and movej lines: the ticks the program spent on them,
heating waits and the time between programs left out), to set against the summary's robot-time estimate.
"""
import csv
import json
import math
import os
import re
import sys


def rotation(rv):
    angle = math.sqrt(sum(c * c for c in rv))
    if angle == 0.0:
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
    x, y, z = (c / angle for c in rv)
    c, s = math.cos(angle), math.sin(angle)
    t = 1.0 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def nozzle_in_platform(pose, tip):
    """The fixed tip seen from the TCP (platform) frame: R^T (tip - p)."""
    r = rotation(pose[3:6])
    d = [tip[i] - pose[i] * 1000.0 for i in range(3)]
    return [sum(r[k][i] * d[k] for k in range(3)) for i in range(3)]


MOVEL = re.compile(r"movel\(p\[([^\]]*)\]")
ANALOG = re.compile(r"set_standard_analog_out\(0, ([0-9.eE+-]+)\)")


def move_lines(script_path):
    """The 1-based numbers of the script's movel and movej lines."""
    with open(script_path) as f:
        return {n for n, line in enumerate(f, 1) if "movel(" in line or "movej(" in line}


def extrusion_segments(script_path, tip):
    segments = []
    analog0 = 0.0
    previous = None
    with open(script_path) as f:
        for line in f:
            a = ANALOG.search(line)
            if a:
                analog0 = float(a.group(1))
            m = MOVEL.search(line)
            if not m:
                continue
            point = nozzle_in_platform([float(v) for v in m.group(1).split(",")], tip)
            if previous is not None and analog0 > 0.0:
                segments.append((previous, point))
            previous = point
    return segments


def distance(p, segment):
    a, b = segment
    d = [b[i] - a[i] for i in range(3)]
    length2 = sum(c * c for c in d)
    t = 0.0
    if length2 > 0.0:
        t = max(0.0, min(1.0, sum((p[i] - a[i]) * d[i] for i in range(3)) / length2))
    return math.sqrt(sum((a[i] + t * d[i] - p[i]) ** 2 for i in range(3)))


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    trace_path, out, cell_path = sys.argv[1:4]
    with open(cell_path) as f:
        tip = json.load(f)["nozzleTipMm"]
    segments = {}
    moves = {}
    for name in sorted(os.listdir(out)):
        m = re.fullmatch(r"step-(\d+)\.script", name)
        if m:
            segments["multidir_step_" + m.group(1)] = extrusion_segments(os.path.join(out, name), tip)
            moves["multidir_step_" + m.group(1)] = move_lines(os.path.join(out, name))
    moving = {name: 0.0 for name in segments}
    last_time = None
    at = {name: 0 for name in segments}
    worst = {name: 0.0 for name in segments}
    total = {name: 0.0 for name in segments}
    ticks = {name: 0 for name in segments}
    window = 4  # moves ahead of the current one a tick may have reached (ticks of 8 ms, moves of 0.1 mm and up)
    with open(trace_path) as f:
        for row in csv.DictReader(f):
            program = row["program"]
            t = float(row["time_s"])
            # A tick's time goes to the statement it was traced at (consecutive 8 ms ticks only).
            if program in moves and last_time is not None and t - last_time < 0.0081 and int(row["line"]) in moves[program]:
                moving[program] += t - last_time
            last_time = t
            if program not in segments or not row["filament_mm_s"] or float(row["filament_mm_s"]) <= 0.0:
                continue
            p = [float(row["nozzle_x_mm"]), float(row["nozzle_y_mm"]), float(row["nozzle_z_mm"])]
            path = segments[program]
            start = at[program]
            best, best_i = math.inf, start
            for i in range(start, min(len(path), start + window + 1)):
                d = distance(p, path[i])
                if d < best:
                    best, best_i = d, i
            if best > 0.05:  # far behind or ahead of the window: the nearest of every move
                for i, move in enumerate(path):
                    d = distance(p, move)
                    if d < best:
                        best, best_i = d, i
            at[program] = best_i
            worst[program] = max(worst[program], best)
            total[program] += best
            ticks[program] += 1
    print("step extruding_ticks max_mm mean_mm moving_s")
    for name in segments:
        n = ticks[name]
        print(f"{name} {n} {worst[name]:.6f} {total[name] / n if n else float('nan'):.6f} {moving[name]:.1f}")


if __name__ == "__main__":
    main()
