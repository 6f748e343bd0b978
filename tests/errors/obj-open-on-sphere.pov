// expect: 2:15: 'open' applies to cylinder and cone only
sphere { 0, 1 open }
