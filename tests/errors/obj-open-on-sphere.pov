// expect: 2:15: 'open' applies to cylinder, cone, prism and sor (and inside an isosurface) only
sphere { 0, 1 open }
