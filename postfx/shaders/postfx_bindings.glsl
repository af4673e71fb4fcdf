// Constants the post effects share between C++ (postfx/postfx_bindings.h includes this file)
// and GLSL. Only #defines and // comments: tests/unit/postfx_settings_test.cpp checks them.
#define POSTFX_BINDING_HISTOGRAM 1
#define POSTFX_BINDING_EXPOSURE 2
#define EXPOSURE_BINS 256
#define EXPOSURE_LOG_MIN -24.0
#define EXPOSURE_LOG_MAX 24.0
#define EXPOSURE_GROUP 16
#define POSTFX_BINDING_DOF_FOCUS 3
#define DOF_TILE 16
#define POSTFX_BINDING_FLARE_VISIBILITY 4
