#include "io/dxf_reader.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>

#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <fmt/format.h>

#include "io/input_error.hpp"

namespace blockdem {
namespace {

// DXF group-code flags of a POLYLINE / LWPOLYLINE (group 70).
constexpr int polyline_closed = 1;
constexpr int polyline_3d_or_mesh = 8 | 16 | 64;  // 3-D polyline, polygon mesh, polyface mesh

std::string_view trimmed(std::string_view s) {
    const auto begin = s.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos) return {};
    return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

// dxflib sizes its arrays by the counts an entity declares (an LWPOLYLINE's vertices, a spline's
// knots and points, a hatch's loops and edges, a leader's vertices): a count larger than the file
// could hold is refused here, so that a corrupt count is a message, not an allocation failure.
std::string count_problem(const std::string& entity, int code, std::string_view value, std::size_t file_bytes) {
    const bool count = (entity == "LWPOLYLINE" && code == 90) || (entity == "SPLINE" && code >= 72 && code <= 74) ||
                       (entity == "HATCH" && code >= 91 && code <= 93) || (entity == "LEADER" && code == 76);
    if (!count) return "";
    long long n = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), n);
    if (error == std::errc{} && end == value.data() + value.size() && n >= 0 && static_cast<std::size_t>(n) <= file_bytes / 4)
        return "";
    return fmt::format("the {} declares a count (group {}) of '{}', which is not a count this file could hold", entity, code,
                       std::string(value.substr(0, 40)));
}

// What the DXF reference says a group code's value is: group codes 10-59, 110-149, 210-239,
// 460-469 and 1010-1059 hold reals; 60-79, 90-99, 160-179, 270-299, 370-389, 400-409, 420-429,
// 440-459 and 1060-1071 whole numbers (290-299 booleans 0/1); the others text or handles.
enum class GroupValue { text, real, whole };

GroupValue group_value(int code) {
    const auto in = [code](int lo, int hi) { return code >= lo && code <= hi; };
    if (in(10, 59) || in(110, 149) || in(210, 239) || in(460, 469) || in(1010, 1059)) return GroupValue::real;
    if (in(60, 79) || in(90, 99) || in(160, 179) || in(270, 299) || in(370, 389) || in(400, 409) || in(420, 429) ||
        in(440, 459) || in(1060, 1071))
        return GroupValue::whole;
    return GroupValue::text;
}

// Why value is not what its group code holds, or "" when it is: all of it a finite number (a
// whole one where the code says). dxflib reads numbers with atof-like calls, which take "4x0"
// as 4, "1e999" as infinity and "nan" as a NaN that drops the vertex: a corrupt coordinate
// would silently move or remove a corner.
std::string number_problem(int code, std::string_view value) {
    const GroupValue kind = group_value(code);
    if (kind == GroupValue::text) return "";
    const std::string_view digits = !value.empty() && value.front() == '+' ? value.substr(1) : value;  // from_chars takes no '+'
    const char* first = digits.data();
    const char* last = digits.data() + digits.size();
    double x = 0.0;
    const auto [end, error] = std::from_chars(first, last, x);
    if (digits.empty() || end != last || (error != std::errc{} && error != std::errc::result_out_of_range)) return "not a number";
    if (error != std::errc{} || !std::isfinite(x)) return "not a finite number";
    // A whole number may be written as a real ("1.0": Pro/ENGINEER writes them so; dxflib's
    // atoi reads them right): only a fraction is refused.
    return kind == GroupValue::whole && x != std::trunc(x) ? "not a whole number" : "";
}

// The entity or header variable a group belongs to, for messages: "the LWPOLYLINE (handle B1)",
// "the LWPOLYLINE" (a drawing without handles), "the header variable $EXTMIN".
struct GroupOwner {
    std::string entity;     ///< the value of the last group 0
    std::string variable;   ///< in the HEADER section: the last group 9
    std::string handle;     ///< group 5 (105 for a DIMSTYLE) of the entity

    std::string text() const {
        if (!variable.empty()) return "the header variable " + variable;
        return fmt::format("the {}{}", entity, handle.empty() ? "" : fmt::format(" (handle {})", handle));
    }
};

// A group value that is not the number its code holds, where it is.
struct BadNumber {
    int line = 0;
    int code = 0;
    std::string value;
    std::string problem;   ///< "not a number", ...
    GroupOwner owner;      ///< its handle filled in when it comes after the value

    std::string text() const {
        return fmt::format("line {}: group {} of {} holds '{}', which is {}", line, code, owner.text(), value, problem);
    }
};

// Why text is not an ASCII DXF drawing, or "" when it looks like one: its first group (after
// 999 comments) opens a SECTION, every group code is a number, every value of a numeric group
// all of it a finite number (number_problem) and the last group is 0 EOF.
// dxflib itself reads anything without complaint, so a wrong file would give an empty drawing.
std::string structure_problem(const std::string& text) {
    if (text.rfind("AutoCAD Binary DXF", 0) == 0)
        return "is a binary DXF, which blockdem does not read: save the drawing as an ASCII DXF";
    std::istringstream in(text);
    std::string code_line, value_line;
    int line = 0;
    bool first = true;
    long long vertices_declared = 0, vertices_seen = 0;   // of an LWPOLYLINE
    std::string last_code_text, last_value_text;
    GroupOwner owner;   // the entity being read (the value of the last group 0)
    std::optional<BadNumber> bad_number;   // told once its entity's handle has been read
    while (std::getline(in, code_line)) {
        ++line;
        const std::string_view code = trimmed(code_line);
        if (code.empty() && in.peek() == EOF) break;  // a final empty line
        int number = 0;
        const auto [end, error] = std::from_chars(code.data(), code.data() + code.size(), number);
        if (code.empty() || error != std::errc{} || end != code.data() + code.size() || number < 0 || number > 1071)
            return first ? "is not a DXF drawing (a DXF file starts with the group '0' 'SECTION')"
                         : fmt::format("is not a valid DXF drawing: line {} should hold a group code (a whole number "
                                       "from 0 to 1071), found '{}'",
                                       line, std::string(code.substr(0, 40)));
        if (!std::getline(in, value_line)) return fmt::format("is not a valid DXF drawing: the group code on line {} has no value", line);
        ++line;
        const std::string_view value = trimmed(value_line);
        if (first && number != 999) {
            if (number != 0 || value != "SECTION") return "is not a DXF drawing (a DXF file starts with the group '0' 'SECTION')";
            first = false;
        }
        if (number == 0 && bad_number) return bad_number->text();
        if (number == 0) {
            // dxflib keeps only the vertices an LWPOLYLINE declares: a count that disagrees would
            // silently cut the outline short.
            if (owner.entity == "LWPOLYLINE" && vertices_declared != vertices_seen)
                return fmt::format("line {}: the LWPOLYLINE before this line declares {} vertices (group 90) but has {}",
                                   line - 1, vertices_declared, vertices_seen);
            owner = {std::string(value), "", ""};
            vertices_declared = vertices_seen = 0;
        }
        if (number == 9) owner.variable = std::string(value);
        if ((number == 5 || number == 105) && owner.handle.empty()) {
            owner.handle = std::string(value);
            if (bad_number) bad_number->owner.handle = owner.handle;
        }
        if (const std::string problem = number_problem(number, value); !problem.empty() && !bad_number)
            bad_number = BadNumber{line, number, std::string(value.substr(0, 40)), problem, owner};
        if (owner.entity == "LWPOLYLINE" && number == 90) std::from_chars(value.data(), value.data() + value.size(), vertices_declared);
        if (owner.entity == "LWPOLYLINE" && number == 10) ++vertices_seen;
        if (const std::string problem = count_problem(owner.entity, number, value, text.size()); !problem.empty())
            return fmt::format("line {}: {}", line, problem);
        last_code_text = std::string(code);
        last_value_text = std::string(value);
        if (number == 0 && value == "EOF") break;  // what follows (a DOS end-of-file mark) is not read
    }
    if (first) return "is not a DXF drawing (it holds no DXF groups)";
    if (bad_number) return bad_number->text();
    if (last_code_text != "0" || last_value_text != "EOF")
        return "ends before its '0' 'EOF' group: the file is truncated or not a complete DXF drawing";
    return "";
}

// $INSUNITS codes (the DXF reference, header variables) blockdem can name.
std::optional<std::string> unit_name(int insunits) {
    switch (insunits) {
        case 1: return "in";
        case 2: return "ft";
        case 4: return "mm";
        case 5: return "cm";
        case 6: return "m";
        case 7: return "km";
        case 10: return "yd";
        default: return std::nullopt;  // 0: unitless, others: rare units
    }
}

// dxflib calls one function per entity; this collects them in file order. A polyline's vertices
// come after its addPolyline (and, for an old-style POLYLINE, end with SEQEND), so a polyline
// is complete when the next entity or block begins, or the file ends. (Not at endSection:
// dxflib calls it between a POLYLINE and its VERTEX entities too.)
class Collector : public DL_CreationAdapter {
public:
    Drawing drawing;

    void addBlock(const DL_BlockData&) override { finish(); in_block_definition_ = true; }
    void endBlock() override { finish(); in_block_definition_ = false; }
    void endSequence() override { finish(); }

    void setVariableInt(const std::string& key, int value, int) override {
        if (key == "$INSUNITS") drawing.declared_units = unit_name(value);
    }

    void addPolyline(const DL_PolylineData& data) override {
        finish();
        if (ignored()) return;
        ++polylines_;
        current_ = start("polyline");
        current_->closed = (data.flags & polyline_closed) != 0;
        if (data.flags & polyline_3d_or_mesh)
            current_->problem = "is a 3-D polyline or a mesh, not a 2-D outline: draw the block as a closed 2-D polyline";
        const double* direction = getExtrusion()->getDirection();
        mirrored_ = direction[2] < 0.0;
        if (direction[0] != 0.0 || direction[1] != 0.0)
            current_->problem = "is drawn in a plane other than the XY plane (its extrusion direction is not +Z or -Z)";
    }

    void addVertex(const DL_VertexData& v) override {
        if (!current_) return;
        // An entity whose extrusion direction is -Z (mirrored in CAD) has x flipped in its own
        // coordinate system (the DXF arbitrary-axis rule).
        current_->vertices.push_back({mirrored_ ? -v.x : v.x, v.y});
        if (v.bulge != 0.0 && current_->problem.empty())
            current_->problem = fmt::format("has an arc segment (bulge {:g}) after its vertex {} at ({:g}, {:g}): "
                                            "blocks have straight edges; replace the arc by straight segments in the drawing",
                                            v.bulge, current_->vertices.size() - 1, v.x, v.y);
    }

    void addLine(const DL_LineData&) override {
        not_a_block("line", "a line: a block is one closed polyline (join the lines into a closed polyline)");
    }
    void addArc(const DL_ArcData&) override { not_a_block("arc", "an arc: blocks have straight edges"); }
    void addCircle(const DL_CircleData&) override {
        not_a_block("circle", "a circle: blocks are polygons; draw it as a closed polyline of straight segments");
    }
    void addEllipse(const DL_EllipseData&) override {
        not_a_block("ellipse", "an ellipse: blocks are polygons; draw it as a closed polyline of straight segments");
    }
    void addSpline(const DL_SplineData&) override {
        not_a_block("spline", "a spline: blocks have straight edges; convert it to a closed polyline of straight segments");
    }
    void addInsert(const DL_InsertData& data) override {
        not_a_block("block reference", fmt::format("a reference to the block definition '{}': explode it so that its "
                                                   "polylines are in model space",
                                                   data.name));
    }
    void addSolid(const DL_SolidData&) override { not_a_block("solid", "a 2-D solid: draw the block as a closed polyline"); }
    void addTrace(const DL_TraceData&) override { not_a_block("trace", "a trace: draw the block as a closed polyline"); }
    void add3dFace(const DL_3dFaceData&) override { not_a_block("3-D face", "a 3-D face: draw the block as a closed polyline"); }
    void addHatch(const DL_HatchData&) override {
        not_a_block("hatch", "a hatch: blocks are closed polylines (put hatches on a layer without blocks)");
    }

    void finish() {
        if (!current_) return;
        std::vector<Vec2>& v = current_->vertices;
        // A last vertex on the first closes the outline whatever the flag says.
        if (v.size() > 1 && v.front() == v.back()) {
            v.pop_back();
            current_->closed = true;
        }
        if (!current_->closed && current_->problem.empty())
            current_->problem = "is open: a block is a closed polyline (close it in the drawing)";
        drawing.entities.push_back(std::move(*current_));
        current_.reset();
    }

private:
    bool ignored() { return in_block_definition_ || getAttributes().isInPaperSpace(); }

    DrawingEntity start(const std::string& type) {
        DrawingEntity e;
        e.layer = getAttributes().getLayer();
        e.type = type;
        const int handle = getAttributes().getHandle();
        if (handle >= 0) {
            e.id = fmt::format("(handle {:X})", handle);
            e.name_suffix = fmt::format("{:X}", handle);
        } else {
            const int number = type == "polyline" ? polylines_ : ++others_;
            e.id = fmt::format("#{}", number);
            e.name_suffix = fmt::format("{}", number);
        }
        return e;
    }

    void not_a_block(const std::string& type, const std::string& problem) {
        finish();
        if (ignored()) return;
        DrawingEntity e = start(type);
        e.problem = "is " + problem;
        drawing.entities.push_back(std::move(e));
    }

    std::optional<DrawingEntity> current_;
    bool mirrored_ = false;
    bool in_block_definition_ = false;
    int polylines_ = 0;   ///< polylines so far, to number those without a handle
    int others_ = 0;
};

}  // namespace

Drawing read_dxf(const std::string& file_text, const std::string& file) {
    // A UTF-8 byte order mark, which some writers put first, is not part of the first group.
    const std::string_view bom = "\xEF\xBB\xBF";
    const std::string text = file_text.rfind(bom, 0) == 0 ? file_text.substr(bom.size()) : file_text;
    if (const std::string problem = structure_problem(text); !problem.empty()) throw InputError({file, "", 0, 0}, problem);
    Collector collector;
    DL_Dxf dxf;
    std::istringstream in(text);
    if (!dxf.in(in, &collector)) throw InputError({file, "", 0, 0}, "dxflib could not read the drawing");
    collector.finish();
    return std::move(collector.drawing);
}

}  // namespace blockdem
