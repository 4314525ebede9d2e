// gear.nff translated by hand to POV-Ray 3.7 (tests/suite/nff_povray.rs).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 1/256 }
#declare F = <1.5, 2.5, 6>;
#declare A = <0, 1, 0>;
#declare U = vnormalize(A - F);
#declare D = vnormalize(vcross(U, <0, 1, 0>));
#declare H = vcross(D, U);
#declare PH = 2 * tan(radians(35 / 2)) * 120 / 119;
#declare PW = PH * 160 / 120;
camera { perspective location F direction U right D * PW up H * PH }
background { color rgb <0.1, 0.1, 0.15> }
// One light without a colour: the SPD's intensity √1/2.
light_source { <3, 6, 5> color rgb 0.5 }
polygon { 4, <-5, 0, -5>, <-5, 0, 5>, <5, 0, 5>, <5, 0, -5>
  pigment { color rgb <0.7, 0.7, 0.7> }
  finish { ambient 0.2 diffuse 0.5 phong 0.5 phong_size 40 reflection 0.5 } }
polygon { 24, <1.500000, 1.200000, -0.500000>, <0.772741, 1.407055, -0.500000>, <1.299038, 1.950000, -0.500000>, <0.565685, 1.765685, -0.500000>, <0.750000, 2.499038, -0.500000>, <0.207055, 1.972741, -0.500000>, <0.000000, 2.700000, -0.500000>, <-0.207055, 1.972741, -0.500000>, <-0.750000, 2.499038, -0.500000>, <-0.565685, 1.765685, -0.500000>, <-1.299038, 1.950000, -0.500000>, <-0.772741, 1.407055, -0.500000>, <-1.500000, 1.200000, -0.500000>, <-0.772741, 0.992945, -0.500000>, <-1.299038, 0.450000, -0.500000>, <-0.565685, 0.634315, -0.500000>, <-0.750000, -0.099038, -0.500000>, <-0.207055, 0.427259, -0.500000>, <-0.000000, -0.300000, -0.500000>, <0.207055, 0.427259, -0.500000>, <0.750000, -0.099038, -0.500000>, <0.565685, 0.634315, -0.500000>, <1.299038, 0.450000, -0.500000>, <0.772741, 0.992945, -0.500000>
  pigment { color rgb <1, 0.6, 0.1> }
  finish { ambient 0.2 diffuse 0.8 phong 0.2 phong_size 15 reflection 0.2 } }
cylinder { <1.8, 0, 0.5>, <1.8, 1.6, 0.5>, 0.4 open
  pigment { color rgb <0.3, 0.6, 1> }
  finish { ambient 0.2 diffuse 0.7 phong 0.3 phong_size 25 reflection 0.3 } }
// T = 0.7 with index 1: POV-Ray scales ambient and diffuse by 1 − filter (given / 0.3).
polygon { 4, <-1.6, 0.1, 1.5>, <-0.4, 0.1, 1.5>, <-0.4, 1.3, 1.5>, <-1.6, 1.3, 1.5>
  pigment { color rgbf <0.6, 1, 0.6, 0.7> }
  finish { ambient 0.2 / 0.3 diffuse 0.2 / 0.3 }
  interior { ior 1 } }
