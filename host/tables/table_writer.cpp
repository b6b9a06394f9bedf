// table_writer.cpp — writes shared/albedo_tables.h.
#include "table_writer.h"

#include <cstdio>
#include <sstream>

namespace vkpt::tables {
namespace {

void writeComment(std::ostream& out, const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line))
        out << "// " << line << "\n";
}

void writeValues(std::ostream& out, const std::vector<double>& values) {
    char buffer[32];
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::snprintf(buffer, sizeof(buffer), "%.7ef", values[i]);
        out << (i % 6 == 0 ? "    " : " ") << buffer << (i + 1 < values.size() ? "," : "");
        if (i % 6 == 5 || i + 1 == values.size()) out << "\n";
    }
}

} // namespace

void writeTablesHeader(std::ostream& out, int size, const std::vector<NamedTable>& tables) {
    out << "// clang-format off\n"
           "// albedo_tables.h — written by vkpt-albedo-tables (host/tables); do not edit.\n"
           "// Directional albedos of the GGX and Charlie sheen lobes for the albedo scaling of\n"
           "// bsdf.h (Kulla and Conty 2017, \"Revisiting Physically Based Shading at "
           "Imageworks\").\n"
           "// A 2D table has "
        << size << " × " << size << " entries: row j (roughness j/" << size - 1
        << ") after row j − 1,\n// column i at √(cos θo) = i/" << size - 1
        << ". A 1D table has one entry per row.\n"
           "// Host-side C++ only: the reference reads these arrays, and the device reads the "
           "same\n"
           "// numbers from a buffer the host uploads (shared/albedo_lookup.h).\n"
           "#ifndef VKPT_ALBEDO_TABLES_H\n"
           "#define VKPT_ALBEDO_TABLES_H\n\n"
           "namespace vkpt::gpu {\n\n"
           "#define VKPT_TABLE(name, n) inline constexpr float name[n] = {\n"
           "#define VKPT_TABLE_END };\n\n";
    for (const NamedTable& table : tables) {
        writeComment(out, table.comment);
        out << "VKPT_TABLE(" << table.name << ", " << table.values.size() << ")\n";
        writeValues(out, table.values);
        out << "VKPT_TABLE_END\n\n";
    }
    out << "#undef VKPT_TABLE\n"
           "#undef VKPT_TABLE_END\n\n"
           "} // namespace vkpt::gpu\n\n"
           "#endif // VKPT_ALBEDO_TABLES_H\n"
           "// clang-format on\n";
}

} // namespace vkpt::tables
