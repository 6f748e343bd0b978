// func-bitwise-range.pov: bitwise_and, bitwise_or and bitwise_xor work on
// 32-bit ints; a value outside their range becomes the smallest int. The
// expected output is what POV-Ray 3.7.0.10 prints. (2.88889e39 came from
// the fuzzer: lucent's old 64-bit cast of it was undefined behaviour.)
#version 3.7;
#debug concat("a ", str(bitwise_and(2.88889e39, 7), 0, 0), "\n")
#debug concat("b ", str(bitwise_or(-1e30, 1), 0, 0), "\n")
#debug concat("c ", str(bitwise_xor(12, 10), 0, 0), "\n")
#debug concat("d ", str(bitwise_or(3e9, 1), 0, 0), "\n")
#debug concat("e ", str(bitwise_and(-5, 7), 0, 0), "\n")
#debug concat("f ", str(bitwise_or(2147483647, 0), 0, 0), "\n")
#debug concat("g ", str(bitwise_or(2147483648, 0), 0, 0), "\n")
#debug concat("h ", str(bitwise_or(-2147483649, 0), 0, 0), "\n")
#debug concat("i ", str(bitwise_or(-2.5, 0), 0, 0), "\n")
