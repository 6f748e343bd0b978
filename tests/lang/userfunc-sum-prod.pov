// checks sum() and prod() with expressions depending on the parameters
#version 3.7;
#declare Geo = function(r, n) { sum(i, 0, n, pow(r, i)) }
#debug concat(str(Geo(0.5, 10), 0, 10), " ", str(Geo(2, 10), 0, 6), "\n")
#declare Choose = function(n, k) { prod(i, 1, k, (n - k + i) / i) }
#debug concat(str(Choose(10, 3), 0, 6), " ", str(Choose(52, 5), 0, 6), "\n")
#declare Wallis = function(n) { prod(i, 1, n, 4*i*i / (4*i*i - 1)) * 2 }
#debug concat(str(Wallis(1000), 0, 6), "\n")
