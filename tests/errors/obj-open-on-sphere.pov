// expect: 2:15: 'open' applies to cylinder, cone and prism only
sphere { 0, 1 open }
