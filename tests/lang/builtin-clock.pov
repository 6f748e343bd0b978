// checks the clock-related built-in variables in a still (non-animated) render
#version 3.7;
#debug concat("clock=", str(clock, 0, 6), "\n")
#debug concat("clock_delta=", str(clock_delta, 0, 6), "\n")
#debug concat("clock_on=", str(clock_on, 0, 6), "\n")
#debug concat("frame_number=", str(frame_number, 0, 6), "\n")
#debug concat("initial_frame=", str(initial_frame, 0, 6), "\n")
#debug concat("final_frame=", str(final_frame, 0, 6), "\n")
#debug concat("initial_clock=", str(initial_clock, 0, 6), "\n")
#debug concat("final_clock=", str(final_clock, 0, 6), "\n")
#if (clock_on = 0) #debug "still image\n" #else #debug "animation\n" #end
