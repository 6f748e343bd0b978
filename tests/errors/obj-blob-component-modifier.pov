// A blob component takes only textures and transformations (POV-Ray: "No matching } in 'sphere'").
// expect: 3:25: expected a texture, pigment, normal, finish, transformation or '}' (a blob component takes no other modifier), found 'no_shadow'
blob { sphere { 0, 1, 1 no_shadow } }
