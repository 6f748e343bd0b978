// checks datetime() with fixed day counts since 2000-01-01 and a format string
#version 3.7;
#debug concat(datetime(0), "\n")
#debug concat(datetime(1.5, "%Y/%m/%d %H:%M"), "\n")
#debug concat(datetime(366.25), "\n")
#debug concat(datetime(-1, "%Y-%m-%d"), "\n")
