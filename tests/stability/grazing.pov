// grazing.pov: a plane seen at grazing angles up to the horizon, and from
// a camera on it (run.sh: grazing-wide, grazing-tele, grazing-near,
// grazing-on-plane). The camera at height H looks along +z, level; the
// image has an odd height (121), so its middle row is the horizon, rays
// exactly parallel to the plane (direction y = 0). F is the length of the
// direction vector: F = 1 sees the floor from 1.2 to 121 units away,
// F = 1000 from 1.2e3 to 1.2e5 units, where the rays meet the plane at
// angles down to 1e-5 radians. The only light is straight above the
// camera, 100*F units up, so along any column of the image the floor can
// only get darker towards the horizon (N.L falls with the distance), from
// 1 to about 0.64.
//
// Cases: H = 1 with F = 1 and F = 1000; H = 1e-9 (a camera one billionth
// above the floor: every ray below the horizon hits it, a few billionths
// away); H = 0 (the camera on the plane: rays below the horizon start on
// it, the middle row's rays lie in it, 0/0 for a naive solver).
//
// Properties, checked on an OpenEXR render (linear, unclamped values):
// no NaN or infinite value, none outside [0, 1]; every pixel is either
// the background or the floor colour times a factor between the ambient
// 0.2 and 0.2 + 0.8 (no black, no other colour); down each column, the
// background and then the floor, whose factor never decreases (shadow
// acne would be a dip); for H > 0, every row above the horizon is
// background and every row below it floor (for H = 0 either is right, as
// long as it is one of the two).
//
// lucent passes every case (at H = 0 it sees only background: rays that
// start on the plane do not hit it). POV-Ray 3.7 passes H = 1 (both
// lenses) and H = 0 (all background too), and fails H = 1e-9: it shows
// no floor at all, its plane ignoring hits nearer than 1e-6 (so a camera
// closer than that to a plane sees through it).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (H) #declare H = 1; #end
#ifndef (F) #declare F = 1; #end

camera {
  location <0, H, 0>
  direction z*F
  right x*image_width/image_height
  up y
}
light_source { <0, 100*F, 0> color rgb 1 }
background { color rgb <0.2, 0.3, 0.6> }
plane { y, 0 pigment { color rgb <0.9, 0.7, 0.4> } finish { ambient 0.2 diffuse 0.8 } }
