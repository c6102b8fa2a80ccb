#!/usr/bin/env python3
"""The peer of `syskit bus replay` in `rake bench` (bench/replay.rb).

Reads a candump log with python-can's CanutilsLogReader and dispatches each
frame to the devices whose CAN filter matches, with one dict per distinct
mask (standard and extended filters apart), as the replay does. Prints the
frames read, the frames each device receives and the seconds taken (wall
and CPU), as JSON.

Usage: python_can_replay.py LOG FILTERS.json
FILTERS.json: [[device, id, mask, extended], ...]
"""
import json
import sys
import time

import can


def dispatch_tables(filters):
    """{extended: [(mask, {id & mask: [device, ...]}), ...]}"""
    groups = {False: {}, True: {}}
    for name, can_id, mask, extended in filters:
        by_id = groups[extended].setdefault(mask, {})
        by_id.setdefault(can_id & mask, []).append(name)
    return {kind: sorted(masks.items()) for kind, masks in groups.items()}


def main():
    path, filters_path = sys.argv[1], sys.argv[2]
    with open(filters_path) as f:
        tables = dispatch_tables(json.load(f))
    received = {}
    frames = 0
    start = time.perf_counter()
    cpu = time.process_time()
    for msg in can.CanutilsLogReader(path):
        frames += 1
        if msg.is_error_frame:
            continue
        arbitration_id = msg.arbitration_id
        for mask, by_id in tables[msg.is_extended_id]:
            names = by_id.get(arbitration_id & mask)
            if names:
                for name in names:
                    received[name] = received.get(name, 0) + 1
    seconds = time.perf_counter() - start
    cpu = time.process_time() - cpu
    json.dump({"frames": frames, "seconds": seconds, "cpu": cpu, "received": received}, sys.stdout)
    print()


if __name__ == "__main__":
    main()
