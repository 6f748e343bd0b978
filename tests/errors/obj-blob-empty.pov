// A blob needs a component (POV-Ray: "Need at least one component in a blob").
// expect: 3:1: a blob needs at least one component (sphere, cylinder or component)
blob { threshold 0.5 pigment { rgb 1 } }
