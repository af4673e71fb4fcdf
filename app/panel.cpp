// ImGui panel: a SettingsVisitor that draws a widget per field, plus stats and actions.
#include "app/panel.h"

#include "app/scene.h"
#include "config/ini.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace vista {
namespace {

class ImGuiVisitor final : public SettingsVisitor {
public:
    bool changed = false;

    void section(const char* name, const char* help) override {
        if (section_open_) ImGui::PopID();
        section_open_ = ImGui::CollapsingHeader(name);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", help);
        if (section_open_) ImGui::PushID(name);
    }
    void field(const FieldInfo& f, bool& v) override {
        if (!section_open_) return;
        changed |= ImGui::Checkbox(f.key, &v);
        tooltip(f, "");
    }
    void field(const FieldInfo& f, int& v, int min, int max) override {
        if (!section_open_) return;
        changed |= ImGui::DragInt(f.key, &v, std::max(1.0f, float(max - min) / 500.0f), min, max, "%d",
                                  ImGuiSliderFlags_AlwaysClamp);
        tooltip(f, range(min, max));
    }
    void field(const FieldInfo& f, float& v, float min, float max) override {
        if (!section_open_) return;
        if (max - min <= 1000.0f)
            changed |= ImGui::SliderFloat(f.key, &v, min, max, "%.4g", ImGuiSliderFlags_AlwaysClamp);
        else  // wide ranges: a drag whose step follows the magnitude
            changed |= ImGui::DragFloat(f.key, &v, std::max(std::abs(v) * 0.01f, 0.001f), min, max, "%.4g",
                                        ImGuiSliderFlags_AlwaysClamp);
        tooltip(f, range(min, max));
    }
    void field(const FieldInfo& f, double& v, double min, double max) override {
        if (!section_open_) return;
        changed |= ImGui::InputDouble(f.key, &v, 0.0, 0.0, "%.6g");
        v = std::clamp(v, min, max);
        tooltip(f, range(min, max));
    }
    void field(const FieldInfo& f, glm::vec3& v, float min, float max) override {
        if (!section_open_) return;
        if (std::string_view(f.key).find("color") != std::string_view::npos)
            changed |= ImGui::ColorEdit3(f.key, &v.x, ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_Float);
        else
            changed |= ImGui::DragFloat3(f.key, &v.x, 0.01f, min, max);
        for (int i = 0; i < 3; ++i) v[i] = std::clamp(v[i], min, max);
        tooltip(f, range(min, max));
    }
    void field(const FieldInfo& f, glm::dvec3& v, double min, double max) override {
        if (!section_open_) return;
        changed |= ImGui::InputScalarN(f.key, ImGuiDataType_Double, &v.x, 3, nullptr, nullptr, "%.3f");
        for (int i = 0; i < 3; ++i) v[i] = std::clamp(v[i], min, max);
        tooltip(f, range(min, max));
    }
    void field(const FieldInfo& f, std::string& v) override {
        if (!section_open_) return;
        changed |= ImGui::InputText(f.key, &v, ImGuiInputTextFlags_EnterReturnsTrue);
        tooltip(f, "");
    }
    void choice(const FieldInfo& f, int& v, std::span<const char* const> names) override {
        if (!section_open_) return;
        changed |= ImGui::Combo(f.key, &v, names.data(), int(names.size()));
        tooltip(f, "");
    }
    // An ordered list of names (the post chain): one row per entry with up / down / remove
    // buttons, drag and drop between rows, and a combo that appends a name not listed yet.
    void sequence(const FieldInfo& f, std::vector<int>& v, std::span<const char* const> names) override {
        if (!section_open_) return;
        ImGui::TextUnformatted(f.key);
        tooltip(f, "");
        ImGui::PushID(f.key);
        for (std::size_t i = 0; i < v.size(); ++i) {
            ImGui::PushID(int(i));
            const bool known = v[i] >= 0 && std::size_t(v[i]) < names.size();
            if (ImGui::ArrowButton("up", ImGuiDir_Up) && i > 0) std::swap(v[i], v[i - 1]), changed = true;
            ImGui::SameLine();
            if (ImGui::ArrowButton("down", ImGuiDir_Down) && i + 1 < v.size()) std::swap(v[i], v[i + 1]), changed = true;
            ImGui::SameLine();
            const bool remove = ImGui::SmallButton("x");
            ImGui::SameLine();
            ImGui::Selectable(known ? names[std::size_t(v[i])] : "?");
            // Drag an entry onto another to move it there (the buttons do the same a step at a time).
            if (ImGui::BeginDragDropSource()) {
                const int from = int(i);
                ImGui::SetDragDropPayload("vista.sequence", &from, sizeof from);
                ImGui::TextUnformatted(known ? names[std::size_t(v[i])] : "?");
                ImGui::EndDragDropSource();
            }
            int moved_from = -1;
            if (ImGui::BeginDragDropTarget()) {
                if (const ImGuiPayload* payload = ImGui::AcceptDragDropPayload("vista.sequence"))
                    moved_from = *static_cast<const int*>(payload->Data);
                ImGui::EndDragDropTarget();
            }
            ImGui::PopID();
            if (moved_from >= 0 && std::size_t(moved_from) < v.size() && std::size_t(moved_from) != i) {
                const int entry = v[std::size_t(moved_from)];
                v.erase(v.begin() + moved_from);
                v.insert(v.begin() + std::ptrdiff_t(i), entry);
                changed = true;
                break;
            }
            if (remove) {
                v.erase(v.begin() + std::ptrdiff_t(i));
                changed = true;
                break;
            }
        }
        std::vector<const char*> missing;
        std::vector<int> indices;
        for (std::size_t n = 0; n < names.size(); ++n) {
            if (std::find(v.begin(), v.end(), int(n)) != v.end()) continue;
            missing.push_back(names[n]);
            indices.push_back(int(n));
        }
        if (!missing.empty() && ImGui::BeginCombo("add", "add...")) {
            for (std::size_t n = 0; n < missing.size(); ++n) {
                if (ImGui::Selectable(missing[n])) {
                    v.push_back(indices[n]);
                    changed = true;
                }
            }
            ImGui::EndCombo();
        }
        ImGui::PopID();
    }
    // A list key: its entries (name and text, clipped so long lists stay cheap) under a node
    // with their count; the selected entry's values are edited as fields, and entries can be
    // added (a copy of the selected one, or a default one) and removed.
    void list(const FieldInfo& f, ListField& entries) override {
        if (!section_open_) return;
        const bool open = ImGui::TreeNode(f.key, "%s (%zu)", f.key, entries.size());
        tooltip(f, "");
        if (!open) return;
        ImGuiStorage& storage = *ImGui::GetStateStorage();
        const ImGuiID selected_id = ImGui::GetID("selected");
        int selected = storage.GetInt(selected_id, -1);
        if (selected >= int(entries.size())) selected = -1;
        if (entries.size() > 0) {
            const float row = ImGui::GetTextLineHeightWithSpacing();
            const float rows = float(std::min<std::size_t>(entries.size(), 8));
            ImGui::BeginChild("entries", ImVec2(0.0f, row * rows + row * 0.5f), true, ImGuiWindowFlags_HorizontalScrollbar);
            ImGuiListClipper clipper;
            clipper.Begin(int(entries.size()));
            while (clipper.Step()) {
                for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                    const std::string label = entries.name(std::size_t(i)) + " = " + entries.text(std::size_t(i)) +
                                              "##" + std::to_string(i);
                    if (ImGui::Selectable(label.c_str(), i == selected)) selected = i == selected ? -1 : i;
                }
            }
            ImGui::EndChild();
        }
        if (ImGui::SmallButton("add")) {
            const std::string text = selected >= 0 ? entries.text(std::size_t(selected)) : entries.defaultText();
            std::string name;
            for (std::size_t n = entries.size() + 1; name.empty(); ++n) {
                name = std::string(f.key) + "_" + std::to_string(n);
                for (std::size_t i = 0; i < entries.size() && !name.empty(); ++i)
                    if (entries.name(i) == name) name.clear();
            }
            if (entries.set(name, text).empty()) {
                selected = int(entries.size()) - 1;
                changed = true;
            }
        }
        if (selected >= 0) {
            ImGui::SameLine();
            if (ImGui::SmallButton("remove")) {
                entries.erase(std::size_t(selected));
                selected = -1;
                changed = true;
            }
        }
        if (selected >= 0) {
            ImGui::PushID(selected);
            ImGui::TextUnformatted((std::string(f.key) + "." + entries.name(std::size_t(selected))).c_str());
            entries.describeEntry(std::size_t(selected), *this);
            ImGui::PopID();
        }
        storage.SetInt(selected_id, selected);
        ImGui::TreePop();
    }
    void finish() {
        if (section_open_) ImGui::PopID();
        section_open_ = false;
    }

private:
    template <class T>
    static std::string range(T min, T max) {
        char text[96];
        std::snprintf(text, sizeof text, "%g..%g", double(min), double(max));
        return text;
    }
    static void tooltip(const FieldInfo& f, const std::string& range) {
        if (!ImGui::IsItemHovered()) return;
        std::string unit = *f.unit ? std::string(" [") + f.unit + "]" : "";
        ImGui::SetTooltip("%s%s%s%s", f.help, unit.c_str(), range.empty() ? "" : "\nrange ", range.c_str());
    }
    bool section_open_ = false;
};

}  // namespace

bool editSettings(Settings& s) {
    ImGuiVisitor v;
    describe(v, s);
    v.finish();
    return v.changed;
}

Panel::Panel(std::filesystem::path scene_file) : scene_file_(std::move(scene_file)) {
    save_path_ = (std::filesystem::path("out") / "scene.ini").string();
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(vistaRoot() / "config/presets", ec))
        if (e.path().extension() == ".ini") presets_.push_back(e.path());
    std::sort(presets_.begin(), presets_.end());
}

bool Panel::draw(Settings& s, const PanelStats& stats) {
    if (!visible) return false;
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(420, 640), ImGuiCond_FirstUseEver);
    bool changed = false;
    if (ImGui::Begin("vista (F1 hides)", &visible)) {
        drawStats(stats);
        if (ImGui::CollapsingHeader("scene", ImGuiTreeNodeFlags_DefaultOpen)) {
            ImGui::TextDisabled("%s", scene_file_.c_str());
            changed |= drawPresets(s);
            drawSave(s);
            if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
        }
        ImGui::Separator();
        changed |= editSettings(s);
    }
    ImGui::End();
    return changed;
}

void Panel::drawStats(const PanelStats& st) {
    if (!ImGui::CollapsingHeader("stats", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Text("%.1f fps  CPU %.2f ms  GPU %.2f ms", st.fps, st.cpu_ms, st.gpu_ms);
    ImGui::Text("time %.2f s%s  reference copy %.3f ms", st.time_s, st.paused ? " (paused)" : "", st.reference_copy_ms);
    ImGui::TextDisabled("%s", st.renderer.c_str());
    if (ImGui::BeginTable("passes", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableSetupColumn("CPU ms");
        ImGui::TableSetupColumn("copies");
        ImGui::TableHeadersRow();
        for (const auto& p : st.passes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn(), ImGui::TextUnformatted(p.name.c_str());
            ImGui::TableNextColumn(), ImGui::Text("%.3f", p.gpu_ms);
            ImGui::TableNextColumn(), ImGui::Text("%.3f", p.cpu_ms);
            ImGui::TableNextColumn(), ImGui::Text("%.2f", st.reference_copy_ms > 0 ? p.gpu_ms / st.reference_copy_ms : 0.0);
        }
        ImGui::EndTable();
    }
    // The day/night cycle ([sky] time_scale) and the light it gives, live.
    const auto counter = [&st](const char* name) {
        const auto it = st.counters.find(name);
        return it == st.counters.end() ? std::nan("") : it->second;
    };
    if (const double h = counter("sky.time_of_day_h"); std::isfinite(h))
        ImGui::Text("time of day %02d:%02d  sun %.1f deg  %.3g lx  pre-exposure %.3g", int(h), int(std::fmod(h, 1.0) * 60.0),
                    counter("sky.sun_elevation_deg"), counter("sky.lux"), counter("sky.pre_exposure"));
    for (const auto& [name, value] : st.counters) ImGui::Text("%s: %.6g", name.c_str(), value);
    ImGui::Text("transient targets: %zu", st.pool_textures);
    if (!st.culled.empty()) {
        std::string culled;
        for (const auto& c : st.culled) culled += (culled.empty() ? "" : ", ") + c;
        ImGui::TextWrapped("culled: %s", culled.c_str());
    }
    for (const auto& e : st.shader_errors) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", e.c_str());
}

bool Panel::drawPresets(Settings& s) {
    if (presets_.empty()) return false;
    std::string current = presets_[std::size_t(preset_)].stem().string();
    bool changed = false;
    if (ImGui::BeginCombo("preset", current.c_str())) {
        for (int i = 0; i < int(presets_.size()); ++i)
            if (ImGui::Selectable(presets_[std::size_t(i)].stem().c_str(), i == preset_)) preset_ = i;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("apply")) {
        Settings next = s;
        InputErrors errors = loadIniFile(presets_[std::size_t(preset_)], next);
        if (errors.empty()) {
            s = next;
            changed = true;
            message_ = "applied preset " + current;
        } else {
            message_ = errors.front().str();
        }
    }
    return changed;
}

void Panel::drawSave(Settings& s) {
    ImGui::InputText("##save", &save_path_);
    ImGui::SameLine();
    if (ImGui::Button("save scene as")) {
        std::filesystem::path file = save_path_;
        std::error_code ec;
        if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
        std::string problem = saveIniFile(file, s);
        message_ = problem.empty() ? "saved " + file.string() : problem;
    }
}

}  // namespace vista
