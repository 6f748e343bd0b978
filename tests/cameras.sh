#!/bin/sh
# tests/cameras.sh: focal blur's sample counts (issue 6). lucent prints
# the camera rays it traced in its statistics; POV-Ray's "Rays:" line gives
# its own (the figures below were read from povray 3.7 renders of the
# same scenes, -D, no antialiasing).
. "${top_srcdir:-.}/tests/lib.sh"

# camera_rays SCENE W H: the camera rays lucent traces.
camera_rays() {
	"$LUCENT" +W"$2" +H"$3" "$1" -D +O"$WORK/out.png" 2> "$WORK/stats.txt" > /dev/null || return 1
	awk '$1 == "camera" { print $2 }' "$WORK/stats.txt"
}

# A flat background: every lens sample has the same colour, so sampling
# stops at POV-Ray's first check point at or after the minimum. The
# counts per pixel are POV-Ray's (4 x 4 renders: Rays / 16).
for case in "1, 50:7" "8, 50:13" "14, 50:19" "20, 50:23" "36, 200:37" "38, 200:41" "1, 12:7" \
	"8, 12:11" "12, 18:15" "5, 6:6" "10:7" "4:4" "6:4" "50, 50:50"; do
	bs=${case%:*}
	want=${case#*:}
	cat > "$WORK/flat.pov" <<EOS
#version 3.7;
background { color rgb 0.5 }
camera { location <0,0,-4> look_at 0 aperture 0.5 focal_point 0 blur_samples $bs }
EOS
	got=$(camera_rays "$WORK/flat.pov" 4 4)
	check "blur_samples $bs on a flat background: $want samples a pixel (got $got / 16)" \
		test "$got" = "$((want * 16))"
done
cat > "$WORK/flat0.pov" <<EOS
#version 3.7;
background { color rgb 0.3 }
camera { location <0,0,-4> look_at 0 aperture 0.5 focal_point 0 blur_samples 1, 50 variance 0 }
EOS
got=$(camera_rays "$WORK/flat0.pov" 4 4)
check "variance 0 always takes the maximum (got $got / 16)" test "$got" = "$((50 * 16))"

# A checker facing the camera, in focus and out of it. POV-Ray: 10034
# camera rays in focus, 33252 out of focus (40 x 30).
cat > "$WORK/focus.pov" <<EOS
#version 3.7;
global_settings { assumed_gamma 1.0 }
plane { z, 5 pigment { checker rgb 0.1 rgb 0.9 } finish { ambient 1 diffuse 0 } }
camera { location 0 look_at z angle 40 aperture 0.4 focal_point <0, 0, FZ> blur_samples 1, 60 variance 1/1000 }
EOS
sed 's/FZ/5/' "$WORK/focus.pov" > "$WORK/in.pov"
sed 's/FZ/2/' "$WORK/focus.pov" > "$WORK/out.pov"
in=$(camera_rays "$WORK/in.pov" 40 30)
out=$(camera_rays "$WORK/out.pov" 40 30)
check "in focus takes far fewer samples than out of focus ($in, $out)" test "$((in * 5))" -lt "$((out * 2))"
check "in focus: within 15% of POV-Ray's 10034 ($in)" test "$in" -gt 8530 -a "$in" -lt 11540
check "out of focus: within 15% of POV-Ray's 33252 ($out)" test "$out" -gt 28260 -a "$out" -lt 38240

finish
