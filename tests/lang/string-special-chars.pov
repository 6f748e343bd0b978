// checks that strings may hold characters that are special elsewhere in the language
#version 3.7;
#debug "single 'quote' ok\n"
#debug "dollar $ percent % hash # brace { } angle < >\n"
#debug "semicolon ; comment // not /* really */\n"
#debug "#declare X = 1; is just text\n"
#ifdef (X) #debug "X defined\n" #else #debug "X not defined\n" #end
