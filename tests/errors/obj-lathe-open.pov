// A lathe has no open (POV-Ray: "No matching } in 'lathe', open found instead").
// expect: 3:32: 'open' applies to cylinder, cone, prism and sor (and inside an isosurface) only
lathe { 3, <0,0>, <1,1>, <1,2> open }
