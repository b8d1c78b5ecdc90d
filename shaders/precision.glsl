// The type of the kernel's geometric arithmetic (--precision): ray origins and directions,
// distances, intersection tests, hit points and secondary-ray offsets use `real`, which is
// float in the default kernel and double when the host compiles it with RT_FP64 defined
// (host/render/trace_pipeline.cpp; the device must have shaderFloat64). Colours stay float either
// way. In fp64 the spheres and triangle corners arrive as doubles (host/packing/scene_packing.cpp);
// the hierarchy's boxes stay float, rounded outward, and are tested in double.
#ifdef RT_FP64
#define real double
#define rvec3 dvec3
#define rvec4 dvec4
#else
#define real float
#define rvec3 vec3
#define rvec4 vec4
#endif
