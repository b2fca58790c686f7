#!/usr/bin/env python3
"""Writes the synthetic demo site of procsim plume (deterministic).

A 6 km x 6 km stone-processing zone: a limestone ridge with two summits in
the north-west, an isolated hill in the east and a valley running south-west
to north-east through the plants.  Outputs (next to this script):
  terrain.asc          ESRI ASCII grid, 100 m cells, elevations in m
  met_week.csv         one week of hourly wind at 10 m (mostly south-west, calm)
  met_gaussian.csv     three days of hourly meteorology with T, mixing height, cloud
  met_history.csv      three years of hourly "historical" meteorology for the
                       Monte Carlo fits (prevailing south-east wind, dry/wet season)
  measured_24h.csv     invented 24-h "monitoring station" values at P1 for the week,
                       to show the measured-vs-predicted plot (not data)
The case files (eulerian.yaml, gaussian.yaml, montecarlo.yaml) are written by hand.
"""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))


def terrain(x, y):
    z = 25.0 + 0.004 * y
    # ridge with two summits (north-west)
    for cx, cy, h, sx, sy in [(1500, 4600, 260, 450, 350), (2600, 5000, 200, 400, 300)]:
        z += h * math.exp(-((x - cx) / sx) ** 2 - ((y - cy) / sy) ** 2)
    # isolated hill (east)
    z += 150 * math.exp(-((x - 4800) / 380) ** 2 - ((y - 2400) / 380) ** 2)
    # valley along the south-west -> north-east diagonal
    d = (x - y) / math.sqrt(2)
    z -= 18 * math.exp(-(d / 500) ** 2)
    return z


def write_terrain():
    n, cell = 60, 100.0
    with open(os.path.join(HERE, "terrain.asc"), "w") as f:
        f.write(f"ncols {n}\nnrows {n}\nxllcorner 0\nyllcorner 0\ncellsize {cell:g}\nNODATA_value -9999\n")
        for r in range(n - 1, -1, -1):
            y = (r + 0.5) * cell
            f.write(" ".join(f"{terrain((c + 0.5) * cell, y):.2f}" for c in range(n)) + "\n")


def write_week(rng):
    with open(os.path.join(HERE, "met_week.csv"), "w") as f:
        f.write("hour,wind_speed_m_s,wind_direction_deg\n")
        d = 225.0
        for h in range(168):
            tod = h % 24
            # calm nights, breezier afternoons; direction wanders around south-west
            u = 0.8 + 1.4 * max(0.0, math.sin(math.pi * (tod - 7) / 14)) + rng.uniform(-0.3, 0.3)
            d = 225.0 + 0.7 * (d - 225.0) + rng.gauss(0, 12)
            f.write(f"{h},{max(u, 0.3):.2f},{d % 360:.1f}\n")


def diurnal(tod):
    return max(0.0, math.sin(math.pi * (tod - 6) / 13))


def met_row(rng, hour, day_of_year, state):
    tod = hour % 24
    wet = 120 <= day_of_year <= 300          # May..October
    # prevailing south-east (150 deg) in the dry season, south-west in the wet one
    mean_dir = 230.0 if wet else 150.0
    state["d"] = mean_dir + 0.8 * (state["d"] - mean_dir) + rng.gauss(0, 18)
    u = 0.7 + 1.6 * diurnal(tod) + rng.gammavariate(2.0, 0.25)
    t = 24 + (3 if not wet else 2) * math.sin(2 * math.pi * (day_of_year - 80) / 365) + 6 * diurnal(tod) + rng.gauss(0, 0.8)
    mh = 250 + 1100 * diurnal(tod) * (0.7 if wet else 1.0) + rng.gammavariate(2.0, 40)
    cloud = min(8.0, rng.gammavariate(4.0 if wet else 1.5, 1.3))
    return u, state["d"] % 360, t, mh, cloud


def write_full(path, rng, hours, first_day):
    state = {"d": 150.0}
    with open(os.path.join(HERE, path), "w") as f:
        f.write("hour,wind_speed_m_s,wind_direction_deg,temperature_C,mixing_height_m,cloud_cover_oktas\n")
        for h in range(hours):
            day = (first_day - 1 + h // 24) % 365 + 1
            u, d, t, mh, c = met_row(rng, h, day, state)
            f.write(f"{h},{u:.2f},{d:.1f},{t:.1f},{mh:.0f},{c:.1f}\n")


def write_measured(rng):
    with open(os.path.join(HERE, "measured_24h.csv"), "w") as f:
        f.write("day,P1 [ug/m3]\n")
        for day in range(1, 8):
            f.write(f"{day},{rng.uniform(80, 135):.1f}\n")


if __name__ == "__main__":
    rng = random.Random(2000)
    write_terrain()
    write_week(rng)
    write_full("met_gaussian.csv", rng, 72, 6)
    write_full("met_history.csv", rng, 3 * 8760, 1)
    write_measured(rng)
