#include "io/dxf_writer.hpp"

#include <algorithm>
#include <fstream>
#include <memory>
#include <sstream>
#include <string_view>

#include <dl_dxf.h>
#include <fmt/format.h>

#include "io/output_file.hpp"

namespace blockdem {
namespace {

// The DXF $INSUNITS code of metres.
constexpr int insunits_metres = 6;

std::vector<std::string> layers_of(const std::vector<LayerPolygon>& blocks) {
    std::vector<std::string> layers;
    for (const LayerPolygon& b : blocks) {
        const std::string name = dxf_layer_name(b.layer);
        if (std::find(layers.begin(), layers.end(), name) == layers.end()) layers.push_back(name);
    }
    return layers;
}

// The sections a CAD program expects before the entities (the order of dxflib's own example):
// header, tables (viewport, line types, layers, text style, view, UCS, application id,
// dimension style, block records) and the model and paper space blocks.
void write_preamble(DL_Dxf& dxf, DL_WriterA& dw, const std::vector<std::string>& layers) {
    dxf.writeHeader(dw);
    dw.dxfString(9, "$INSUNITS");
    dw.dxfInt(70, insunits_metres);
    dw.sectionEnd();
    dw.sectionTables();
    dxf.writeVPort(dw);
    dw.tableLinetypes(3);
    for (const char* type : {"BYBLOCK", "BYLAYER", "CONTINUOUS"}) dxf.writeLinetype(dw, DL_LinetypeData(type, "", 0, 0, 0.0));
    dw.tableEnd();
    dw.tableLayers(static_cast<int>(layers.size()) + 1);
    dxf.writeLayer(dw, DL_LayerData("0", 0), DL_Attributes("", 7, 100, "CONTINUOUS", 1.0));
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const int colour = 1 + static_cast<int>(k % 6);  // AutoCAD colours 1 to 6: red to magenta
        dxf.writeLayer(dw, DL_LayerData(layers[k], 0), DL_Attributes("", colour, 100, "CONTINUOUS", 1.0));
    }
    dw.tableEnd();
    dw.tableStyle(1);
    dxf.writeStyle(dw, DL_StyleData("standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
    dw.tableEnd();
    dxf.writeView(dw);
    dxf.writeUcs(dw);
    dw.tableAppid(1);
    dxf.writeAppid(dw, "ACAD");
    dw.tableEnd();
    dxf.writeDimStyle(dw, 1, 1, 1, 1, 1);
    dxf.writeBlockRecord(dw);
    dw.tableEnd();
    dw.sectionEnd();
    dw.sectionBlocks();
    for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
        dxf.writeBlock(dw, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
        dxf.writeEndBlock(dw, block);
    }
    dw.sectionEnd();
}

}  // namespace

std::string dxf_layer_name(const std::string& name) {
    if (name.empty()) return "0";
    std::string out = name;
    for (char& c : out)
        if (std::string_view("<>/\\\":;?*|=`").find(c) != std::string_view::npos) c = '_';
    return out;
}

void write_dxf(const std::filesystem::path& file, const std::vector<LayerPolygon>& blocks) {
    // dxflib writes through its own stream with no error report: it writes a scratch file, which
    // is checked for its end and then written through OutputFile (a full disk, a size limit).
    const std::filesystem::path scratch = file.string() + ".partial";
    {
        DL_Dxf dxf;
        std::unique_ptr<DL_WriterA> dw(dxf.out(scratch.c_str(), DL_Codes::AC1015));
        if (!dw || dw->openFailed()) throw OutputError(fmt::format("{}: cannot open for writing", scratch.string()));
        write_preamble(dxf, *dw, layers_of(blocks));
        dw->sectionEntities();
        for (const LayerPolygon& b : blocks) {
            const int closed = 1;
            dxf.writePolyline(*dw, DL_PolylineData(static_cast<int>(b.vertices_m.size()), 0, 0, closed),
                              DL_Attributes(dxf_layer_name(b.layer), 256, -1, "BYLAYER", 1.0));
            for (const Vec2& v : b.vertices_m) dxf.writeVertex(*dw, DL_VertexData(v.x, v.y, 0.0, 0.0));
            dxf.writePolylineEnd(*dw);
        }
        dw->sectionEnd();
        dxf.writeObjects(*dw);
        dxf.writeObjectsEnd(*dw);
        dw->dxfEOF();
        dw->close();
    }
    std::ifstream in(scratch, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    std::error_code ignored;
    std::filesystem::remove(scratch, ignored);
    const std::string content = text.str();
    if (content.size() < 4 || content.find("EOF", content.size() - 8) == std::string::npos)
        throw OutputError(fmt::format("{}: cannot write: the drawing was cut short (is the disk full?)", file.string()));
    write_output_file(file, content);
}

}  // namespace blockdem
