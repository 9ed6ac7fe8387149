// The shading kernel of sunglint, in order: every file of functions it is made of, after
// its interface (kernel/interface.glsl: the structs the host fills and reads). The C++
// side includes the interface and this file (kernel/kernel_double.h,
// kernel/cpu/kernel_float.cpp); the GL engine expands the same includes into one compute
// shader after the GLSL prelude (kernel/glsl_prelude.glsl). Each file opens with what it
// computes and where its formulas come from.
// clang-format off
#include "kernel/constants.glsl"
#include "kernel/wave_terms.glsl"
#include "kernel/special.glsl"
#include "kernel/rng.glsl"
#include "kernel/camera.glsl"
#include "kernel/waves.glsl"
#include "kernel/path_terms.glsl"
#include "kernel/cascade_grid.glsl"
#include "kernel/light.glsl"
#include "kernel/radiance.glsl"
#include "kernel/disk_coverage.glsl"
#include "kernel/horizon_coverage.glsl"
#include "kernel/intersect.glsl"
#include "kernel/footprint.glsl"
#include "kernel/aliasing.glsl"
#include "kernel/ndf.glsl"
#include "kernel/visible_normals.glsl"
#include "kernel/rdf.glsl"
#include "kernel/gaussian.glsl"
#include "kernel/arc.glsl"
#include "kernel/path_table_grid.glsl"
#include "kernel/path_table.glsl"
#include "kernel/path_table_gen.glsl"
#include "kernel/kernel_fit.glsl"
#include "kernel/reflection_path.glsl"
#include "kernel/reflection_footprint.glsl"
#include "kernel/smooth_terms.glsl"
#include "kernel/cascade_fields.glsl"
#include "kernel/staa_waves.glsl"
#include "kernel/staa.glsl"
#include "kernel/sampling.glsl"
#include "kernel/specaa.glsl"
#include "kernel/reference_path.glsl"
#include "kernel/poly6_roots.glsl"
#include "kernel/light_conic.glsl"
#include "kernel/reference.glsl"
// clang-format on
