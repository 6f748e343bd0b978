// string-unicode-escapes.pov: \uNNNN escapes and chr() above U+007F under
// the default charset (ascii) are one character each, kept with their
// code: strlen, asc, substr and strcmp (POV-Ray's: the difference of the
// first codes that differ) count them so; #debug and #write print each
// non-ASCII character as one space. The expected output is what POV-Ray
// 3.7.0.10 prints.
#version 3.7;
#declare S = "a\u0416b\u00e9c\u20ACd";
#debug concat("len ", str(strlen(S), 0, 0), "\n")
#debug concat("asc ", str(asc(substr(S, 2, 1)), 0, 0), " ", str(asc(substr(S, 4, 1)), 0, 0), " ",
              str(asc(substr(S, 6, 1)), 0, 0), " ", str(asc(substr(S, 7, 1)), 0, 0), "\n")
#debug concat("S [", S, "]\n")
#debug concat("up [", strupr(S), "] lw [", strlwr(S), "]\n")
#debug concat("sub [", substr(S, 2, 3), "] ", str(strlen(substr(S, 2, 3)), 0, 0), "\n")
#debug concat("chr [", chr(1046), "] ", str(strlen(chr(1046)), 0, 0), " ", str(asc(chr(1046)), 0, 0), "\n")
#debug concat("[", chr(126), chr(127), chr(128), chr(160), chr(233), chr(255), chr(256), "]\n")
#debug concat("[\u00e9] [\u007f] [\u0080] [\u00ff] [\u0100] [\uffff]\n")
#debug concat(str(asc("\uffff"), 0, 0), " ", str(asc(chr(65535)), 0, 0), " ", str(asc("\u00ff"), 0, 0), "\n")
#debug concat("cmp ", str(strcmp("\u0416", "\u0417"), 0, 0), " ", str(strcmp("\u0416", "z"), 0, 0), " ",
              str(strcmp("z", "\u00e9"), 0, 0), " ", str(strcmp("\u0100", "\u00ff"), 0, 0), "\n")
#debug concat("cmp ", str(strcmp("a", "c"), 0, 0), " ", str(strcmp("abc", "ab"), 0, 0), " ",
              str(strcmp("ab", "abc"), 0, 0), " ", str(strcmp("same", "same"), 0, 0), "\n")
#declare W = concat("a\u0416", chr(255), "b");
#debug concat(str(strlen(W), 0, 0), " ", str(asc(substr(W, 3, 1)), 0, 0), " ", str(asc(substr(W, 2, 2)), 0, 0), "\n")
#fopen F "string-unicode-escapes.txt" write
#write (F, "\"x\u0416y\u00e9z\"\n")
#fclose F
#fopen F "string-unicode-escapes.txt" read
#read (F, L)
#fclose F
#debug concat("read [", L, "] ", str(strlen(L), 0, 0), "\n")
