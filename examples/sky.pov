// sky.pov: the procedural environment of examples/sky.png, an equirectangular
// (latitude-longitude) image of 360 x 180 degrees for scn's `skybox { image ... }`.
// Render: povray -D +A0.05 +AM2 +R3 +W1024 +H512 +FN8 +Isky.pov +Osky.png
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare SunDir = vnormalize(<-0.55, 0.45, -0.7>);    // towards the sun, in scene coordinates
#declare Sx = SunDir.x; #declare Sy = SunDir.y; #declare Sz = SunDir.z;
#declare Haze = rgb <0.80, 0.87, 0.95>;
// scn (like POV-Ray's map_type 1) puts column u = 0 towards +x, growing towards +z, and
// the top row straight up. This camera puts +z in the middle and +x to its right, so
// the world is mirrored by M: (x,y,z) -> (-z,y,-x) to make the image come out that way.
#declare M = transform { matrix <0,0,-1, 0,1,0, -1,0,0, 0,0,0> }
camera { spherical angle 360 180 location <0,0,0> look_at <0,0,1> }
#declare Bozo = function { pigment { bozo turbulence 0.7 octaves 6 omega 0.55 lambda 2.1
                                     color_map { [0 rgb 0] [1 rgb 1] } scale <1.6,1,0.9> } }
sky_sphere {
  pigment { function { min(max(y,0),1) } poly_wave 0.5
            color_map { [0 Haze] [1 rgb <0.10,0.28,0.72>] } }
  // clouds: a flat layer seen in perspective, thinning out towards the horizon
  pigment { function { min(1, max(0, (Bozo(x/(y+0.03), 0, z/(y+0.03)).gray - 0.52)*4) * min(1, y*5)) }
            color_map { [0 rgbt <1,1,1,1>] [0.5 rgbt <1,1,1,0.35>] [1 rgbt <0.93,0.94,0.97,0>] } }
  // the sun: a bright disc with a soft glow
  pigment { function { pow(max(0, x*Sx + y*Sy + z*Sz), 400) }
            color_map { [0 rgbt <1,0.85,0.6,1>] [0.2 rgbt <1,0.9,0.7,0.6>] [0.9 rgbt <1,1,0.9,0>] [1 rgb 1] } }
  transform { M }
}
// ground: a checker of two grass greens, fading into haze at the horizon
plane { y, -1.7
  texture { pigment { checker rgb <0.18,0.40,0.10>, rgb <0.32,0.56,0.15> }
            finish { ambient 0.35 diffuse 0.65 } }
  texture { pigment { function { min(1, sqrt(x*x + z*z)/60) } poly_wave 0.7
                      color_map { [0 Haze transmit 1] [1 Haze transmit 0] } }
            finish { ambient 1 diffuse 0 } }
  transform { M } }
light_source { SunDir*1000 color rgb 1 transform { M } }
