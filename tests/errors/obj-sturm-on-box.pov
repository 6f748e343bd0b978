// expect: 2:13: 'sturm' applies to torus, cubic, quartic, poly and prism only
box { -1, 1 sturm }
