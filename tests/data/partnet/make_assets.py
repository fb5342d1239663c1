#!/usr/bin/env python3
"""Writes the hand-made test tools in the layout of PartNet-Mobility: each
tool a folder with mobility.urdf (a base link, a fixed joint to link_0, the
fixed part, and a revolute joint to link_1, the moving part) and its parts
as OBJ boxes under textured_objs/, one box a file as PartNet-Mobility keeps
one part a file. Lengths below in mm; the files are in metres.

    python3 tests/data/partnet/make_assets.py   # from the repository's root

The geometry says what afford model must find (tests/test_modelling_tools.cpp):
- scissors (type 1, balance): blades 6..110 mm whose faces meet, handles
  -80..-6 mm whose inner faces stand 4 mm back, so their gap never closes;
  the moving part lies opened by 20 deg, its joint from -25 to +10 deg: the
  blades meet at -20 deg (theta_min 0, where they meet), theta_max 30 deg.
- stapler (type 3): a base and a top 150 mm long hinged at the back; only the
  staple head (120..150 mm) reaches down to the base, the rest of the top
  stands 3 mm above it. Joint 0 closed, 0..25 deg.
- garlic press (type 2): a chamber and a plunger 20..60 mm from the hinge
  that meet, handles 60..200 mm that stand 3 mm back each. Joint 0 closed,
  0..35 deg.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def box_obj(lo, hi, turn_deg=0.0):
    """An OBJ box from corner lo to corner hi (mm), turned about z by turn_deg, in metres."""
    c, s = math.cos(math.radians(turn_deg)), math.sin(math.radians(turn_deg))
    lines = []
    for i in range(8):
        p = [hi[k] if (i >> k) & 1 else lo[k] for k in range(3)]
        x, y = c * p[0] - s * p[1], s * p[0] + c * p[1]
        lines.append("v %.9g %.9g %.9g" % (x / 1000, y / 1000, p[2] / 1000))
    # Each face counter-clockwise seen from outside (1-based corners).
    for q in ((1, 5, 7, 3), (2, 4, 8, 6), (1, 2, 6, 5), (3, 7, 8, 4), (1, 3, 4, 2), (5, 6, 8, 7)):
        lines.append("f %d %d %d" % (q[0], q[1], q[2]))
        lines.append("f %d %d %d" % (q[0], q[2], q[3]))
    return "\n".join(lines) + "\n"


def write_tool(name, fixed, moving, turn_deg, lower_deg, upper_deg):
    """fixed, moving: {part name: (lo, hi)} boxes in mm; the moving ones turned by turn_deg."""
    folder = os.path.join(HERE, name)
    os.makedirs(os.path.join(folder, "textured_objs"), exist_ok=True)

    def elements(parts, turn):
        out = []
        for part, (lo, hi) in parts.items():
            with open(os.path.join(folder, "textured_objs", part + ".obj"), "w") as f:
                f.write(box_obj(lo, hi, turn))
            for tag in ("visual", "collision"):
                out.append('    <%s name="%s"><origin xyz="0 0 0"/><geometry><mesh filename="textured_objs/%s.obj"/>'
                           '</geometry></%s>' % (tag, part, part, tag))
        return "\n".join(out)

    urdf = """<?xml version="1.0"?>
<!-- Written by make_assets.py (tests/data/partnet): %s in the layout of PartNet-Mobility. -->
<robot name="%s">
  <link name="base"/>
  <link name="link_0">
%s
  </link>
  <link name="link_1">
%s
  </link>
  <joint name="joint_0" type="fixed">
    <origin xyz="0 0 0" rpy="0 0 0"/>
    <parent link="base"/>
    <child link="link_0"/>
  </joint>
  <joint name="joint_1" type="revolute">
    <origin xyz="0 0 0" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
    <parent link="link_0"/>
    <child link="link_1"/>
    <limit lower="%.9g" upper="%.9g" effort="1" velocity="1"/>
  </joint>
</robot>
""" % (name, name, elements(fixed, 0.0), elements(moving, turn_deg), math.radians(lower_deg), math.radians(upper_deg))
    with open(os.path.join(folder, "mobility.urdf"), "w") as f:
        f.write(urdf)


# Scissors: the two pieces in layers (z) that slide past each other.
write_tool("scissors",
           {"blade-0": ((6, -8, -2), (110, 0, 0)), "handle-0": ((-80, 4, -2), (-6, 16, 0)),
            "hub-0": ((-6, -6, -2), (6, 6, 0))},
           {"blade-1": ((6, 0, 0), (110, 8, 2)), "handle-1": ((-80, -16, 0), (-6, -4, 2)),
            "hub-1": ((-6, -6, 0), (6, 6, 2))},
           20.0, -25.0, 10.0)
# Stapler: the top's head reaches the base; the rest stands 3 mm above it.
write_tool("stapler",
           {"base-0": ((0, -20, -15), (150, 0, 15))},
           {"top-1": ((0, 3, -10), (120, 18, 10)), "head-1": ((120, 0, -10), (150, 18, 10))},
           0.0, 0.0, 25.0)
# Garlic press: chamber and plunger meet; the handles stand back.
write_tool("garlic-press",
           {"hinge-0": ((0, -25, -12), (20, -20, 12)), "chamber-0": ((20, -25, -12), (60, 0, 12)),
            "handle-0": ((60, -15, -8), (200, -3, 8))},
           {"hinge-1": ((0, 10, -12), (20, 15, 12)), "plunger-1": ((20, 0, -10), (60, 10, 10)),
            "handle-1": ((60, 3, -8), (200, 15, 8))},
           0.0, 0.0, 35.0)
