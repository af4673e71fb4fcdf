// Spatiotemporal blue noise (renderer/blue_noise.h): the void-and-cluster map tiled over the
// image, shifted by the golden ratio each frame so a pixel's values over frames are evenly
// spread (Wolfe et al. 2022). Bound to BINDING_BLUE_NOISE for every pass by FrameRenderer.
#define BLUE_NOISE_SIZE 64
layout(binding = BINDING_BLUE_NOISE) uniform sampler2D u_blue_noise;

// A value in [0, 1) for pixel p in frame `frame`; `channel` decorrelates several estimators of
// one pixel (each reads the map at a different offset).
float blueNoise(ivec2 p, uint frame, int channel) {
    ivec2 q = (p + ivec2(channel * 23, channel * 41)) & (BLUE_NOISE_SIZE - 1);
    float v = texelFetch(u_blue_noise, q, 0).r;
    return fract(v + float(frame % 4096u) * 0.61803398875);
}
