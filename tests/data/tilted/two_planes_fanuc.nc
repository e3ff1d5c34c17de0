%
O0001 (NCPOST)
(ncpost 0.1.0 from tests/data/tilted/two_planes.cls)
(machine ac-trunnion [machines/ac-trunnion.toml])
(workpiece origin 0.0000 0.0000 80.0000 mm, tool length 0.0000 mm)
(model none [nominal machine], tolerance none)
(machine axes, no RTCP)
G90 G21 G94 G17 G40 G49 G80
(Two positional [3+2] operations on two tilted planes, between a vertical start and end:)
(plane 1 [tool axis tipped 30 deg toward -Y]: a pocket contour with a quarter CIRCLE )
(plane 2 [tool axis tipped 40 deg, 30 deg round from +X]: two drilled holes [CYCLE/DRILL].)
(Written for tests/postproc/tilted_plane_test.cpp [ncpost's own test data].)
(PARTNO TILTED PLANES)
T1 M6
G43 H1
S8000 M3
G0 X0.0000 Y0.0000 Z180.0000 A0.0000 C0.0000
G68.2 X10.0000 Y-40.0000 Z144.6410 I0.0000 J30.0000 K0.0000
G53.1
G0 X0.0000 Y0.0000 Z34.7372
Z0.0000
Z-35.0000
G94 G1 Z-40.0000 F300.0
X15.0000
Y10.0000
G3 X5.0000 Y20.0000 Z-40.0000 I-10.0000 J0.0000
G1 X0.0000 Y5.0000
Z-10.0000
G69
G0 X10.0000 Y42.6795 Z180.0000 A-30.0000 C0.0000
X0.0000 Y0.0000 A0.0000
G1 X20.0000 Z120.0000
Z115.0000 F400.0
Z140.0000
G68.2 X-1.0832 Y18.0348 Z119.1511 I-60.0000 J-40.0000 K0.0000
G53.1
G0 X-0.0001 Y0.0000 Z43.5317
Z0.0000
G98 G81 X-0.0001 Y0.0000 Z-30.0000 R-22.0000 F100.0
X-12.0001
G80
G0 Z25.0000
G69
G0 X-28.1603 Y-70.3997 Z180.0000 A40.0000 C60.0000
X0.0000 Y0.0000 A0.0000
M5
M9
G91 G28 Z0
G90
M30
%
