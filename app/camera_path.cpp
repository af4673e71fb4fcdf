// Camera paths: reads key poses from a text file and gives a smooth pose at any time, so
// captures and fly-throughs follow a scripted route that passes exactly through its keys.
//
// Position: centripetal Catmull-Rom (Barry-Goldman knots, alpha = 0.5) in Hermite form.
// The tangent dP/du at a key is converted to one velocity dP/dt per key, so both segments
// meeting at a key leave and enter it with the same velocity (C1 in time, not only in the
// knot parameter). Angles use the same Hermite scheme with time as the knot parameter,
// yaw on values unwrapped along the shortest arc. End keys use the zero-curvature
// ("natural") condition: the second derivative is zero at the first and last key.
#include "app/camera_path.h"
#include "config/file_io.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

namespace vista {
namespace {

constexpr std::array<const char*, 7> kFieldNames{"t", "x", "y", "z", "yaw_deg", "pitch_deg", "fov_deg"};
constexpr double kMinFov = 1.0, kMaxFov = 179.0, kMaxPitch = 90.0;
// Bounds that keep the interpolation finite: positions as far out as the scene file allows
// ([camera] position), times to 30,000 years, yaw to a million degrees of winding, and keys at
// least a millisecond apart (velocities stay below 1e12 m/s, products in the Hermite basis
// finite).
constexpr double kMaxPosition = 1e8, kMaxTime = 1e12, kMaxYaw = 1e6, kMinStep = 1e-3;
// Smallest centripetal knot spacing: coincident positions would otherwise divide by zero.
constexpr double kMinKnot = 1e-9;

std::string format(double v) {
    std::array<char, 32> buf{};
    auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    return ec == std::errc() ? std::string(buf.data(), end) : std::string("?");
}

// Parses a whole token as a double; nullopt when any character is left over.
std::optional<double> parseNumber(std::string_view token) {
    // from_chars rejects a leading '+', which people write naturally.
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
    double v = 0.0;
    auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (end != token.data() + token.size()) return std::nullopt;
    if (ec == std::errc::result_out_of_range) return HUGE_VAL;  // reported as non-finite
    if (ec != std::errc()) return std::nullopt;
    return v;
}

std::vector<std::string_view> splitFields(std::string_view line) {
    constexpr std::string_view kSpace = " \t\r\f\v";
    std::vector<std::string_view> fields;
    std::size_t pos = line.find_first_not_of(kSpace);
    while (pos != std::string_view::npos) {
        std::size_t end = line.find_first_of(kSpace, pos);
        fields.push_back(line.substr(pos, end == std::string_view::npos ? end : end - pos));
        pos = line.find_first_not_of(kSpace, end);
    }
    return fields;
}

double normalizeYaw(double yaw) {
    yaw = std::remainder(yaw, 360.0);  // [-180, 180]
    return yaw <= -180.0 ? yaw + 360.0 : yaw;
}

// Derivative at b of the non-uniform Catmull-Rom curve through a, b, c with knot
// spacings d0 (a..b) and d1 (b..c) (Barry-Goldman pyramid, differentiated at b).
template <class T>
T catmullRomTangent(const T& a, const T& b, const T& c, double d0, double d1) {
    return (b - a) / d0 - (c - a) / (d0 + d1) + (c - b) / d1;
}

// Cubic Hermite on a segment of duration h, s in [0, 1]; exact at s = 0 and s = 1.
template <class T>
T hermite(const T& p0, const T& p1, const T& v0, const T& v1, double h, double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2.0 * s3 - 3.0 * s2 + 1.0) * p0 + (s3 - 2.0 * s2 + s) * h * v0 + (-2.0 * s3 + 3.0 * s2) * p1 +
           (s3 - s2) * h * v1;
}

// One channel (position, yaw, ...) at up to four consecutive keys around the sampled
// segment. du: knot spacing of each interval, dt: its duration. first/last say whether
// the window's ends are the path's ends, the only place the end condition is needed.
template <class T>
struct Window {
    std::array<T, 4> p{};
    std::array<double, 3> du{}, dt{};
    std::size_t n = 0;

    // Velocity d/dt at window key k.
    T velocity(std::size_t k) const {
        if (n == 2) return (p[1] - p[0]) / dt[0];
        // Natural end: zero second derivative of the Hermite segment at the end key.
        if (k == 0) return 0.5 * (3.0 * (p[1] - p[0]) / dt[0] - velocity(1));
        if (k == n - 1) return 0.5 * (3.0 * (p[n - 1] - p[n - 2]) / dt[n - 2] - velocity(n - 2));
        // One rate du/dt per key (over both neighbouring intervals), so the segments on
        // either side share the velocity.
        const double rate = (du[k - 1] + du[k]) / (dt[k - 1] + dt[k]);
        return catmullRomTangent(p[k - 1], p[k], p[k + 1], du[k - 1], du[k]) * rate;
    }
};

}  // namespace

CameraPath::CameraPath(std::vector<CameraKey> keys) : keys_(std::move(keys)) {
    // Interpolation needs strictly increasing times: sort, and keep the first of equal times.
    std::stable_sort(keys_.begin(), keys_.end(), [](const CameraKey& a, const CameraKey& b) { return a.t < b.t; });
    auto same_time = [](const CameraKey& a, const CameraKey& b) { return a.t == b.t; };
    keys_.erase(std::unique(keys_.begin(), keys_.end(), same_time), keys_.end());
}

// Keys written 0.001 s apart differ by a rounded 0.001 (0.301 - 0.3 < 0.001 in binary), so the
// minimum step is compared with a tolerance of a few ulps of the time.
static double stepTolerance(double t) { return 1e-9 + 8.0 * std::numeric_limits<double>::epsilon() * std::abs(t); }

CameraPath CameraPath::parse(std::string_view text, const std::string& name, InputErrors& errors,
                             double default_fov_deg) {
    std::vector<CameraKey> keys;
    double inherited_fov = default_fov_deg;
    // Time of the last line that was in order, even when that line failed for another
    // reason, so one misplaced time is reported once rather than on every following line.
    std::optional<double> previous_t;
    int key_lines = 0;
    int line_no = 0;
    auto report = [&](std::string message) { errors.push_back({name, line_no, std::move(message)}); };
    // A UTF-8 byte order mark (editors on Windows add one) is not a field: it was reported as
    // an invisible "t is not a number".
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);

    for (std::size_t pos = 0; pos < text.size();) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++line_no;

        line = line.substr(0, line.find('#'));
        const std::vector<std::string_view> fields = splitFields(line);
        if (fields.empty()) continue;
        ++key_lines;
        if (fields.size() != 6 && fields.size() != 7) {
            report("expected 't x y z yaw_deg pitch_deg [fov_deg]', got " + std::to_string(fields.size()) +
                   " fields");
            continue;
        }

        std::array<double, 7> v{};
        bool numbers_ok = true;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            const std::string token(fields[i]);
            const std::optional<double> number = parseNumber(fields[i]);
            if (!number) {
                report(std::string(kFieldNames[i]) + " is not a number: '" + token + "'");
                numbers_ok = false;
            } else if (!std::isfinite(*number)) {
                report(std::string(kFieldNames[i]) + " must be a finite number, got '" + token + "'");
                numbers_ok = false;
            } else {
                v[i] = *number;
            }
        }
        if (!numbers_ok) continue;

        bool ok = true;
        if (std::abs(v[0]) > kMaxTime) {
            report("t " + format(v[0]) + " is outside -1e12..1e12 seconds");
            ok = false;
        } else if (previous_t && (v[0] <= *previous_t || v[0] - *previous_t < kMinStep - stepTolerance(v[0]))) {
            report("time " + format(v[0]) + " must be greater than the previous key's time " + format(*previous_t) +
                   " (times increase strictly, by at least 0.001 s)");
            ok = false;
        } else {
            previous_t = v[0];
        }
        for (std::size_t i = 1; i <= 3; ++i)
            if (std::abs(v[i]) > kMaxPosition) {
                report(std::string(kFieldNames[i]) + " " + format(v[i]) + " is outside -1e8..1e8 m");
                ok = false;
            }
        if (std::abs(v[4]) > kMaxYaw) {
            report("yaw_deg " + format(v[4]) + " is outside -1e6..1e6 degrees");
            ok = false;
        }
        if (v[5] < -kMaxPitch || v[5] > kMaxPitch) {
            report("pitch_deg " + format(v[5]) + " is outside -90..90 degrees");
            ok = false;
        }
        const double fov = fields.size() == 7 ? v[6] : inherited_fov;
        if (fov < kMinFov || fov > kMaxFov) {
            report("fov_deg " + format(fov) + " is outside 1..179 degrees");
            ok = false;
        } else {
            inherited_fov = fov;
        }
        if (ok) keys.push_back({v[0], CameraPose{{v[1], v[2], v[3]}, v[4], v[5], fov}});
    }

    if (key_lines < 2) {
        line_no = 0;
        report("a camera path needs at least 2 keys, found " + std::to_string(key_lines));
    }
    // With errors the path holds only the good keys; callers are expected to check errors.
    return CameraPath(std::move(keys));
}

CameraPath CameraPath::load(const std::filesystem::path& file, InputErrors& errors, double default_fov_deg) {
    // Regular files under a size limit only: a FIFO blocked forever and /dev/zero filled memory.
    std::string text;
    if (std::string why = readInputFile(file, kMaxTextInputBytes, text); !why.empty()) {
        errors.push_back({file.string(), 0, "camera path " + why.substr(std::min(why.size(), file.string().size() + 2))});
        return CameraPath();
    }
    return parse(text, file.string(), errors, default_fov_deg);
}

double CameraPath::startTime() const { return keys_.empty() ? 0.0 : keys_.front().t; }

double CameraPath::endTime() const { return keys_.empty() ? 0.0 : keys_.back().t; }

CameraPose CameraPath::sample(double t) const {
    auto finish = [](CameraPose pose) {
        pose.yaw_deg = normalizeYaw(pose.yaw_deg);
        pose.pitch_deg = std::clamp(pose.pitch_deg, -kMaxPitch, kMaxPitch);
        pose.fov_deg = std::clamp(pose.fov_deg, kMinFov, kMaxFov);
        return pose;
    };
    if (keys_.empty()) return {};
    if (keys_.size() == 1) return finish(keys_.front().pose);

    t = std::isnan(t) ? startTime() : std::clamp(t, startTime(), endTime());
    // Segment i runs from key i to key i + 1.
    const auto after = std::upper_bound(keys_.begin(), keys_.end(), t,
                                        [](double time, const CameraKey& k) { return time < k.t; });
    const std::size_t last = keys_.size() - 1;
    const std::size_t i = std::min<std::size_t>(std::max<std::ptrdiff_t>(after - keys_.begin() - 1, 0), last - 1);

    // Keys i-1 .. i+2 where they exist.
    const std::size_t lo = i > 0 ? i - 1 : 0;
    const std::size_t hi = std::min(i + 2, last);
    Window<glm::dvec3> pos;
    Window<double> yaw, pitch, fov;
    for (std::size_t j = lo; j <= hi; ++j) {
        const std::size_t k = j - lo;
        const CameraPose& pose = keys_[j].pose;
        pos.p[k] = pose.position;
        pitch.p[k] = pose.pitch_deg;
        fov.p[k] = pose.fov_deg;
        yaw.p[k] = pose.yaw_deg;
        if (k > 0) {
            const double dt = keys_[j].t - keys_[j - 1].t;
            pos.dt[k - 1] = yaw.dt[k - 1] = pitch.dt[k - 1] = fov.dt[k - 1] = dt;
            // Centripetal: knot spacing is the square root of the distance.
            pos.du[k - 1] = std::max(std::sqrt(glm::length(pos.p[k] - pos.p[k - 1])), kMinKnot);
            yaw.du[k - 1] = pitch.du[k - 1] = fov.du[k - 1] = dt;
        }
    }
    pos.n = yaw.n = pitch.n = fov.n = hi - lo + 1;

    // Unwrap yaw so that every step is the short way round (170 -> -170 goes via 180),
    // anchored at key i so that the curve passes through its yaw exactly.
    const std::size_t k0 = i - lo, k1 = k0 + 1;
    // Steps come from the raw key yaws, so every segment unwraps a key pair the same way.
    const std::array<double, 4> raw = yaw.p;
    for (std::size_t k = k0 + 1; k < yaw.n; ++k) yaw.p[k] = yaw.p[k - 1] + std::remainder(raw[k] - raw[k - 1], 360.0);
    if (k0 > 0) yaw.p[0] = yaw.p[1] - std::remainder(raw[1] - raw[0], 360.0);
    const double h = keys_[i + 1].t - keys_[i].t;
    const double s = (t - keys_[i].t) / h;
    auto interpolate = [&](const auto& w) { return hermite(w.p[k0], w.p[k1], w.velocity(k0), w.velocity(k1), h, s); };

    CameraPose pose;
    pose.position = interpolate(pos);
    pose.yaw_deg = interpolate(yaw);
    pose.pitch_deg = interpolate(pitch);
    pose.fov_deg = interpolate(fov);
    return finish(pose);
}

}  // namespace vista
