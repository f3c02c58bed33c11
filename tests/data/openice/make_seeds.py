#!/usr/bin/env python3
"""Seeds for lungar_openice_samples_fuzz (scripts/fuzz copies them into its corpus): one ice::SampleArray of each
followed metric, in XCDR1 little-endian as Cyclone receives it, behind the target's first byte (bit 4 XCDR2, bit 5
byte-swapped, the value modulo 3 the followed quantity: 0 volume, 1 flow, 2 pressure). The volume array carries a
negative value and a NaN, which the checks must drop."""
import os
import struct


def cdr_string(text):
    b = text.encode() + b"\0"
    out = struct.pack("<I", len(b)) + b
    return out + b"\0" * (-len(out) % 4)


def sample_array(metric, unit, frequency, values, pick):
    body = (cdr_string("vent-1") + cdr_string(metric) + cdr_string("") + struct.pack("<i", 0) + cdr_string(unit) +
            struct.pack("<i", frequency) + struct.pack("<I", len(values)) +
            b"".join(struct.pack("<f", v) for v in values) + struct.pack("<ii", 1000, 200000000) * 2)
    return bytes([pick]) + body


here = os.path.dirname(os.path.abspath(__file__))
seeds = {
    "volume.cdr": sample_array("MDC_VOL_AWAY_TIDAL", "MDC_DIM_MILLI_L", 50, [0, 100, 200, -5, float("nan")], 0),
    "flow.cdr": sample_array("MDC_FLOW_AWAY", "MDC_DIM_L_PER_MIN", 50, [30, 60, -20], 1),
    "pressure.cdr": sample_array("MDC_PRESS_AWAY", "MDC_DIM_CM_H2O", 100, [5, 10, 20], 2),
}
for name, data in seeds.items():
    with open(os.path.join(here, name), "wb") as f:
        f.write(data)
