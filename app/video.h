// H.264 video from captured frames, through Debian's `ffmpeg` program on a pipe: vista decodes
// each PNG/EXR frame (OpenImageIO) and writes raw RGB to ffmpeg's stdin, so frames may come
// from several shard directories. ffmpeg writes to a temporary name beside the video, renamed
// only once it exited cleanly: a failed or interrupted encode never leaves a video under the
// final name. The program is $VISTA_FFMPEG when set (tests use it to make the encoder fail),
// else `ffmpeg` on the PATH.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vista {

struct VideoOptions {
    double fps = 24.0;  // frames per second of the video (a capture's --fps plays in real time)
    int crf = 18;       // H.264 constant rate factor, 0 (lossless) .. 51
    bool force = false; // replace an existing video
};

// Encodes frames (all the same size) in order into file (.mp4). "" on success, else the
// message (ffmpeg's own on failure). Odd sizes are padded to even (yuv420p needs it).
std::string encodeVideo(const std::vector<std::filesystem::path>& frames, const std::filesystem::path& file,
                        const VideoOptions& options);

// The frame_NNNN.png (or .exr) files of dir in frame order; problems lists gaps in the
// numbering and a mix of formats (then the list is still returned).
std::vector<std::filesystem::path> findFrameSequence(const std::filesystem::path& dir, std::vector<std::string>& problems);

}  // namespace vista
