// expect: 4:8: chr(70000): a character code is 0 to 65535
// POV-Ray's characters are 16-bit codes (POV-Ray 3.7: "Value 70000 cannot
// be used in chr()").
#debug chr(70000)
