// expect: 2:1: expected an object, light_source, camera, global_settings, background or directive, found '}'
}
