// benches/pov/orbit.pov: benches/pov/orbit.txt (a snapshot of scenes/orbit.txt) written by
// hand for POV-Ray 3.7, for the speed comparison of benches/pov/compare.sh.
//
//   povray +Iorbit.pov +W640 +H480 +WT2 -A -D +FN File_Gamma=1 +KFI0 +KFF249 +KI0 +KF249 Declare=Frames=250
//
// The clock counts frames (+KI0 +KF<N-1> with +KFI0 +KFF<N-1>: clock = frame number), so
// frame i puts the camera at angle 360·i/Frames on the orbit of radius 12 at height 3
// around (0, 1, 0), as `animate`'s circle path does (SPEC §5). Rendered without a clock it
// is frame 0, the scene file's own camera (0, 3, 12).
//
// POV-Ray is left-handed: every z of the Scene.txt is negated here. The report's model in
// POV-Ray's terms:
// - camera: direction of length 1, right 0.5, up 0.35 (the report's 0.5 x 0.35 view at 1.0);
// - ambient 0.2·C (ambient 0.2, ambient_light 1); diffuse Kd; specular (1 - Kd)·(V·R)^20 =
//   phong (1 - Kd), phong_size 20;
// - reflection Kr; transmission Kt as the pigment's filter, interior ior Ior;
// - 5 bounces after the primary ray = max_trace_level 6 (POV-Ray counts the primary ray);
//   the weight cut-off 1/256 = adc_bailout 1/256;
// - fog type 2 (exponential, D = 50) = POV-Ray's fog_type 1, distance 50, white;
// - the checker is on unit cubes, as ours; the noise textures use POV-Ray's own noise
//   (bozo; bozo at 40x frequency for the report's noise "wood"; marble), so they look
//   alike without being identical: this file is for timing, not for pixel comparison;
// - the pillar is infinite in Scene.txt: here it runs from y = -1000 to 1000;
// - no gamma, as in the report (assumed_gamma 1, and File_Gamma=1 on the command line).
#version 3.7;

#ifndef (Frames) #declare Frames = 250; #end
#declare Angle = 2 * pi * clock / Frames;

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 1
  max_trace_level 6
  adc_bailout 1/256
}

camera {
  perspective
  location <12 * sin(Angle), 3, -12 * cos(Angle)>
  direction <0, 0, 1>
  right <0.5, 0, 0>
  up <0, 0.35, 0>
  sky <0, 1, 0>
  look_at <0, 1, 0>
}

light_source { <-7.61, 8, -2.47> color rgb <1, 1, 1> * 0.7 }
light_source { <4.70, 6, 6.47> color rgb <1, 0.95, 0.85> * 0.5 }

fog { fog_type 1 distance 50 color rgb 1 }

#macro Fin(Kd, Kr)
  finish { ambient 0.2 diffuse Kd phong (1 - Kd) phong_size 20 reflection { Kr } }
#end

// glass (0°), floating 0.02 above the floor
sphere { <0, 0.62, -1.9>, 0.6
  pigment { color rgbf <1, 1, 1, 0.9> } Fin(0, 0.1) interior { ior 1.5 } }
// mirror (72°)
sphere { <1.807, 0.6, -0.587>, 0.6
  pigment { color rgb <0.2, 0.2, 0.2> } Fin(0.2, 0.8) }
// Perlin (144°): a three-stop ramp on the noise
sphere { <1.117, 0.6, 1.537>, 0.6
  pigment { bozo color_map { [0 rgb <0.8, 0.05, 0>] [0.5 rgb <0.95, 0.75, 0.1>] [1 rgb <1, 1, 1>] } }
  Fin(0.7, 0) }
// "wood" (216°): the ramp repeated 20 times per unit of noise
sphere { <-1.117, 0.6, 1.537>, 0.6
  pigment { bozo frequency 40 cubic_wave color_map { [0 rgb <0.55, 0.3, 0.1>] [1 rgb <0.3, 0.15, 0.05>] } }
  Fin(0.7, 0) }
// marble (288°)
sphere { <-1.807, 0.6, -0.587>, 0.6
  pigment { marble turbulence 0.5 sine_wave color_map { [0 rgb <0.95, 0.93, 0.85>] [1 rgb <0.55, 0.05, 0.1>] } }
  Fin(0.7, 0) }
// the sky dome (hollow, or POV-Ray draws no fog inside it)
sphere { <0, 0, 0>, 1000
  pigment { color rgb <0.7, 0.8, 0.95> } Fin(1, 0) hollow }
// the checker floor, slightly polished
plane { y, 0
  pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.25, 0.3, 0.4> }
  Fin(0.8, 0.2) }
// the pillar, "infinite"
cylinder { <0, -1000, 0>, <0, 1000, 0>, 0.35
  pigment { color rgb <0.9, 0.85, 0.75> } Fin(0.7, 0) }
