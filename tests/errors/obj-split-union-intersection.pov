// expect: 2:48: 'split_union' applies to union only
intersection { sphere { 0, 1 } sphere { x, 1 } split_union off }
