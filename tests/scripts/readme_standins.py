"""Stand-ins for the user's own files that the README's commands name (a label map, a lung surface, a breathing
trace, a stylus pivoting and touching landmarks, SPAAM alignments), written into the folder the commands run in.
Each is small, so that the commands it feeds take seconds, and each is what the README says the command reads."""
import math
import os
import random
import struct
import zlib

# The .trk log (drivers/trk/trk_format.h), little-endian: header "LUNGATRK" | version u32 | description | layout
# (length-prefixed) | CRC-32; then records: sync u16 0x4B52 | source u8 | reserved u8 | length u16 | t_ns u64 |
# report | CRC-32 of source .. report.
TRK_SYNC = 0x4B52
TRK_SOURCE_HID = 0
# The layout in the header: the defaults of config/default.toml with the stylus enabled (station 3).
TRK_LAYOUT = "[trackers.stylus]\nenabled = true\n"
# config/default.toml's [trackers.report]: 32-byte reports, id 1, station byte at 1, u32 microseconds at 2, each
# sensor's block at 6: position i32 x, y, z at 0.01 mm, quaternion w, x, y, z in Q2.14 at block + 12.
STATION = {"head": 1, "patient": 2, "stylus": 3}
PERIOD_NS = 16_000_000


def _trk_header():
    body = b"LUNGATRK" + struct.pack("<I", 1)
    for text in ("source=readme-standin\n", TRK_LAYOUT):
        raw = text.encode()
        body += struct.pack("<I", len(raw)) + raw
    return body + struct.pack("<I", zlib.crc32(body))


def _report(role, position_mm, quat_wxyz, ticks_us):
    report = bytearray(32)
    report[0] = 1
    report[1] = STATION[role]
    struct.pack_into("<I", report, 2, ticks_us & 0xFFFFFFFF)
    struct.pack_into("<3i", report, 6, *(round(c * 100) for c in position_mm))
    struct.pack_into("<4h", report, 18, *(round(c * 16384) for c in quat_wxyz))
    return bytes(report)


def _record(report, t_ns):
    body = struct.pack("<BBHQ", TRK_SOURCE_HID, 0, len(report), t_ns) + report
    return struct.pack("<H", TRK_SYNC) + body + struct.pack("<I", zlib.crc32(body))


def _quat_mul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw)


def _rotate(q, v):
    w, x, y, z = _quat_mul(_quat_mul(q, (0.0, *v)), (q[0], -q[1], -q[2], -q[3]))
    return (x, y, z)


def _axis_angle(axis, angle):
    s = math.sin(angle / 2)
    return (math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s)


# A stylus whose sensor sits 150 mm up the handle from its tip (its frame), on a patient tracker at the origin.
STYLUS_TIP_MM = (2.0, -1.5, -150.0)
# Four landmarks of the model (lung frame = patient frame here: the registration comes out the identity).
LANDMARKS_MM = [(-80.0, -150.0, -100.0), (90.0, -140.0, -110.0), (0.0, -230.0, -300.0), (70.0, -90.0, -60.0)]


def write_stylus_log(path, tips_mm, hold, seed):
    """A .trk log of the stylus held with its tip on each of `tips_mm` for `hold` reports (16 ms apart), tilting
    up to 0.6 rad about x and y, beside the patient tracker's report."""
    rng = random.Random(seed)
    out = bytearray(_trk_header())
    t_ns = 1_000_000_000
    for tip in tips_mm:
        for _ in range(hold):
            q = _quat_mul(_axis_angle((1, 0, 0), rng.uniform(-0.6, 0.6)), _axis_angle((0, 1, 0), rng.uniform(-0.6, 0.6)))
            q_tip = _rotate(q, STYLUS_TIP_MM)
            sensor = tuple(t - r + rng.gauss(0.0, 0.05) for t, r in zip(tip, q_tip))
            ticks = t_ns // 1000
            out += _record(_report("patient", (0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0), ticks), t_ns)
            out += _record(_report("stylus", sensor, q, ticks), t_ns)
            t_ns += PERIOD_NS
    with open(path, "wb") as f:
        f.write(out)


def write_model_csv(path):
    with open(path, "w") as f:
        f.write("# the model's landmarks, x, y, z in mm (lung frame)\n")
        f.writelines(f"{x},{y},{z}\n" for x, y, z in LANDMARKS_MM)


def write_alignments_csv(path):
    """SPAAM alignments of a known HMD: each eye a pinhole 31.5 mm either side of the head sensor, looking along +z
    (800 px focal length, 1280x720 viewport), 25 points 0.3-0.9 m deep spread across the view."""
    rng = random.Random(7)
    lines = ["eye,x_mm,y_mm,z_mm,u_px,v_px"]
    for eye, ex in (("left", -31.5), ("right", 31.5)):
        for _ in range(25):
            z = rng.uniform(300.0, 900.0)
            u, v = rng.uniform(100.0, 1180.0), rng.uniform(80.0, 640.0)
            x = ex + (u - 640.0) * z / 800.0
            y = (v - 360.0) * z / 800.0
            lines.append(f"{eye},{x:.3f},{y:.3f},{z:.3f},{u:.2f},{v:.2f}")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_sphere_stl(path, radius_mm=60.0, subdivisions=4):
    """A binary STL of an icosphere (2,562 vertices at 4 subdivisions): a closed genus-0 surface of about 0.9 L,
    within what a lung can be, in mm."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
             (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [tuple(c / math.sqrt(sum(k * k for k in v)) for c in v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(subdivisions):
        midpoints = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoints:
                m = [(p + q) / 2 for p, q in zip(verts[a], verts[b])]
                n = math.sqrt(sum(c * c for c in m))
                verts.append(tuple(c / n for c in m))
                midpoints[key] = len(verts) - 1
            return midpoints[key]

        faces = [f for a, b, c in faces for f in ((a, midpoint(a, b), midpoint(c, a)), (b, midpoint(b, c),
                                                   midpoint(a, b)), (c, midpoint(c, a), midpoint(b, c)),
                                                  (midpoint(a, b), midpoint(b, c), midpoint(c, a)))]
    with open(path, "wb") as f:
        f.write(b"readme stand-in: an icosphere".ljust(80, b" ") + struct.pack("<I", len(faces)))
        for face in faces:
            corners = [tuple(c * radius_mm for c in verts[i]) for i in face]
            normal = tuple(sum(c[k] for c in corners) / 3 for k in range(3))
            f.write(struct.pack("<3f", *normal))
            for c in corners:
                f.write(struct.pack("<3f", *c))
            f.write(b"\0\0")


def write_trace_csv(path):
    """A breathing belt's trace, `t_s,value`: 60 s at 25 Hz, 15 breaths a minute, inhale up."""
    with open(path, "w") as f:
        f.write("t_s,value\n")
        f.writelines(f"{i / 25:.2f},{math.sin(2 * math.pi * (i / 25) / 4):.4f}\n" for i in range(60 * 25))


def write_all(folder, root):
    """Every stand-in, into `folder`; the label map is the shipped one (labels 2 and 3, as the README's)."""
    join = lambda name: os.path.join(folder, name)  # noqa: E731
    os.symlink(os.path.join(root, "sim", "data", "lungs", "10002K_INSP_STD_BWH_COPD_leftLungRightLung.nrrd"),
               join("seg.nrrd"))
    write_sphere_stl(join("lung.stl"))
    write_trace_csv(join("trace.csv"))
    write_stylus_log(join("pivot.trk"), [(10.0, -20.0, 30.0)], hold=200, seed=11)
    write_stylus_log(join("touches.trk"), LANDMARKS_MM, hold=50, seed=12)
    write_model_csv(join("model.csv"))
    write_alignments_csv(join("alignments.csv"))
