// expect: 4:47: expected pigment or '}' in bokeh, found 'rgb'
#version 3.7;
sphere { 0, 1 }
camera { aperture 0.5 blur_samples 10 bokeh { rgb 1 } }
