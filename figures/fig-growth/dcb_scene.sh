#!/usr/bin/env bash
# dcb_scene.sh METHOD H [F_T]: the growing DCB of
# tests/7-fracture/scenes/dcb_growth.cfg (100 x 36 mm, crack 50 mm long,
# E = 0.1 MPa, nu = 0.33, plane stress, opened at its end at up to 4e-3
# mm/ms each arm, 600 ms, damping 0.02) at resolution H, to standard
# output, for make fig-growth.
#   mpm H    CRAMP: cells of 100/N x H mm (N the odd whole number nearest
#            100/H, so that the tip at x = 50 is mid-cell, as in
#            dcb_growth.cfg), 2 x 2 points per cell, the node column x = 0
#            opened (all its nodes but the one on the crack, x free); the
#            J contours at about 4, 6 and 8 mm (whole cells), G_c =
#            5e-5 N/mm, average 2 ms, segments of half a cell (default).
#   xefg H F_T   XEFG: one point per cell of H x H, so the nodes are H
#            apart, the crack on a cell line between two rows; the first
#            column of points (x = H/2) is opened, as the grid cannot hold
#            material in XEFG; the crack cohesive, linear, G_f = 5e-5 N/mm
#            (= G_c) and f_t = F_T MPa, segments of H (default), the
#            tip turned by the largest hoop stress of K_I, K_II
#            (direction = "hoop", chapter 6b).
# Each arm's end is moved, not loaded: the opening is the same function
# of time for both methods (at x = 0 or x = H/2: the FEA puts its end
# there, figures/fig-growth/dcb_fea.c).
set -u
m=$1 h=$2 ft=${3:-}
awk -v m="$m" -v h="$h" -v ft="$ft" '
    function f(v,  s) { s = sprintf("%.17g", v); return (s ~ /[.e]/) ? s : s ".0" }
    function ceil(v) { return (v == int(v)) ? v : int(v) + 1 }
    BEGIN {
        ny = ceil(22 / h - 1e-9); y0 = -ny * h
        printf "# written by figures/fig-growth/dcb_scene.sh %s %s %s:\n", m, h, ft
        print  "# tests/7-fracture/scenes/dcb_growth.cfg at another resolution"
        if (m == "mpm") {
            N = int(100 / h + 0.5); if (N % 2 == 0) N++
            dx = 100 / N
            printf "grid = { origin = [%s, %s]; cells = [%d, %d];\n", f(-dx), f(y0), N + 2, 2 * ny
            printf "         cell_size = [%s, %s]; };\n", f(dx), f(h)
            print  "run = { time = 600.0; cfl = 0.5; damping = 0.02; snapshots = 6; };"
            ppc = 2; rect = "min = [0.0, -18.0]; max = [100.0, 18.0];"
            xa = -0.1; xb = 0.1; ya = 0.5 * h
            c = int(4 / dx + 0.5); c2 = int(6 / dx + 0.5); c3 = int(8 / dx + 0.5)
            if (c2 <= c) c2 = c + 1
            if (c3 <= c2) c3 = c2 + 1
            crack = sprintf("cracks = ( { points = ( [%s, 0.0], [50.0, 0.0] );\n" \
                "             j_integral = { every = 5; contours = [%d, %d, %d]; };\n" \
                "             growth = { G_c = 5e-5; average = 2.0; }; } );", f(-dx), c, c2, c3)
        } else {
            nx = ceil(104 / h - 1e-9) + 1
            printf "grid = { origin = [%s, %s]; cells = [%d, %d];\n", f(-h), f(y0), nx, 2 * ny
            printf "         cell_size = [%s, %s]; };\n", f(h), f(h)
            print  "run = { time = 600.0; cfl = 0.5; damping = 0.02; snapshots = 6; method = \"xefg\"; };"
            ppc = 1; rect = "min = [0.0, -18.0]; max = [100.0, 18.0];"
            xa = 0.0; xb = h; ya = 0.1 * h
            crack = sprintf("cracks = ( { points = ( [%s, 0.0], [50.0, 0.0] );\n" \
                "             cohesive = { law = \"linear\"; f_t = %s; G_f = 5e-5;\n" \
                "                          growth = { direction = \"hoop\"; }; }; } );", f(-h), f(ft))
        }
        print  "materials = ( { name = \"soft\"; E = 0.1; nu = 0.33; rho = 1.5e-3; } );"
        printf "bodies = ( { name = \"dcb\"; material = \"soft\"; points_per_cell = %d;\n", ppc
        printf "             rectangle = { %s }; } );\n", rect
        print  "boundaries = ("
        printf "  { rectangle = { min = [%s, %s]; max = [%s, %s]; }; fix = \"y\";\n", f(xa), f(ya), f(xb), f(-y0)
        print  "    velocity = [0.0, 4e-3]; ramp = 50.0; },"
        printf "  { rectangle = { min = [%s, %s]; max = [%s, %s]; }; fix = \"y\";\n", f(xa), f(y0), f(xb), f(-ya)
        print  "    velocity = [0.0, -4e-3]; ramp = 50.0; }"
        print  ");"
        print crack
    }'
