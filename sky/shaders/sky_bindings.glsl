// Binding points of the sky's own GL resources, shared by C++ (sky/atmosphere.cpp includes
// this file) and GLSL. Only #defines and // comments.
#define SKY_BINDING_ATMOSPHERE 1
#define SKY_IMAGE_AERIAL_TRANSMITTANCE 1
#define SKY_BINDING_CLOUDS 2
#define SKY_TEX_CLOUD_SHADOW 7
// Wavelengths of the transmitted sunlight's colour (sunlightRgb; sky/atmosphere_spectral.h
// kSunlightWavelengths, checked by a static_assert).
#define SKY_SUNLIGHT_WAVELENGTHS 21
