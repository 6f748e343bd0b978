// checks the string relational operators < <= = >= > !=
#version 3.7;
#declare TestCase = "ABC";
#macro Show(N, V) #debug concat(N, "=", str(V, 0, 0), "\n") #end
Show("ABC<ABD", (TestCase < "ABD"))
Show("ABC<=ABC", (TestCase <= "ABC"))
Show("ABC=ABC", (TestCase = "ABC"))
Show("ABC!=abc", (TestCase != "abc"))
Show("ABC>AB", (TestCase > "AB"))
Show("ABC>=ABD", (TestCase >= "ABD"))
Show("a>B", ("a" > "B"))
Show("empty<a", ("" < "a"))
