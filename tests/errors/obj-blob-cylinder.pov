// A cylinder component's ends must differ (POV-Ray: "Degenerate cylindrical component in blob").
// expect: 3:8: a blob's cylinder component needs two different ends (POV-Ray: degenerate cylindrical component)
blob { cylinder { <1,0,0>, <1,0,0>, 1, 1 } }
