#!/usr/bin/env bash
# An OFF mesh (OFF header, counts, vertices, triangles; blank lines allowed) as an ascii PLY whose
# vertices carry distinct RGBA colors, for the tests that check colors survive simplification.
#   colored_ply.sh IN.off OUT.ply
awk 'NF == 0 { next } ++n == 1 { next } n == 2 { nv = $1; nf = $2;
       print "ply\nformat ascii 1.0\nelement vertex " nv;
       print "property float x\nproperty float y\nproperty float z";
       print "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha";
       print "element face " nf "\nproperty list uchar int vertex_indices\nend_header"; next }
     n > 2 && n <= 2 + nv { printf "%s %s %s %d %d %d 255\n", $1, $2, $3, (n * 7) % 256, (n * 13) % 256, (n * 29) % 256; next }
     n > 2 + nv { print }' "$1" >"$2"
