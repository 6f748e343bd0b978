// expect: 2:35: max_trace_level must be between 1 and 256
global_settings { max_trace_level 0 }
