// still-life.nff translated by hand to POV-Ray 3.7 (tests/suite/nff_povray.rs): the
// camera of SPEC §17 (angle between the outer pixel centres), no gamma, the same depth.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 1/256 }
#declare F = <0, -6, 2.5>;
#declare A = <0, 0, 0.8>;
#declare U = vnormalize(A - F);
#declare D = vnormalize(vcross(U, <0, 0, 1>));
#declare H = vcross(D, U);
#declare PH = 2 * tan(radians(20)) * 120 / 119;
#declare PW = PH * 160 / 120;
camera { perspective location F direction U right D * PW up H * PH }
background { color rgb <0.2, 0.3, 0.5> }
light_source { <4, -3, 6> color rgb sqrt(2) / 4 }
light_source { <-5, -4, 4> color rgb <0.6, 0.6, 0.5> }
polygon { 4, <-4, -4, 0>, <4, -4, 0>, <4, 4, 0>, <-4, 4, 0>
  pigment { color rgb <0.9, 0.8, 0.6> } finish { ambient 0.2 diffuse 0.8 } }
sphere { <-1.2, 0.5, 1>, 1
  pigment { color rgb <0.8, 0.2, 0.2> }
  finish { ambient 0.2 diffuse 0.6 phong 0.4 phong_size 30 reflection 0.4 } }
// T = 0.8: POV-Ray scales ambient and diffuse by 1 − filter, so they are given / 0.2.
sphere { <1.1, -0.8, 0.7>, 0.7
  pigment { color rgbf <0.9, 1, 0.9, 0.8> }
  finish { ambient 1.0 diffuse 0.5 phong 0.2 phong_size 60 reflection 0.2 }
  interior { ior 1.5 } }
cone { <2, 1.5, 0>, 0.8, <2, 1.5, 2>, 0.1 open
  pigment { color rgb <0.2, 0.4, 0.9> }
  finish { ambient 0.2 diffuse 0.7 phong 0.3 phong_size 10 reflection 0.3 } }
smooth_triangle { <-2.5, -1.5, 0.01>, <-0.5, 0, 1>, <-0.5, -2.5, 0.01>, <0.5, 0, 1>,
  <-1.5, -1, 1.5>, <0, -0.6, 0.8>
  pigment { color rgb <0.3, 0.9, 0.3> }
  finish { ambient 0.2 diffuse 0.8 phong 0.2 phong_size 20 reflection 0.2 } }
