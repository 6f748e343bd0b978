// expect: 2:13: 'sturm' applies to torus, cubic, quartic and poly only
box { -1, 1 sturm }
