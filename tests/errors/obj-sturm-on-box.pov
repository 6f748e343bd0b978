// expect: 2:13: 'sturm' applies to torus, cubic, quartic, poly, prism, lathe and sor only
box { -1, 1 sturm }
