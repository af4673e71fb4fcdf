// The subset march ([clouds] march_subset): each frame "clouds.shell" marches one pixel of every
// stride x stride block of the cloud target, into a target 1/stride its size whose texel q stands
// for pixel stride * q + cloudSubsetOffset(); "clouds.temporal" fills in the rest. The offset
// walks the block in Bayer order over the sequence index (u_time.z), so any stride^2 consecutive
// frames mark every pixel once and consecutive offsets lie far apart.
ivec2 cloudSubsetOffset(int stride, uint index) {
    uint i = index % uint(stride * stride);
    if (stride == 2) {  // Bayer 2x2: value = 2 (x ^ y) + y
        int y = int(i & 1u);
        return ivec2(int((i >> 1) & 1u) ^ y, y);
    }
    if (stride == 4) {  // Bayer 4x4: value bits (x ^ y)_0, y_0, (x ^ y)_1, y_1, most significant first
        int y = int((i >> 2) & 1u) | (int(i & 1u) << 1);
        int xy = int((i >> 3) & 1u) | (int((i >> 1) & 1u) << 1);
        return ivec2(xy ^ y, y);
    }
    return ivec2(0);
}
