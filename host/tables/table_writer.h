// table_writer.h — the albedo tables as the constants of a header that compiles both as C++ and
// as GLSL (shared/albedo_tables.h).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace vkpt::tables {

struct NamedTable {
    std::string name;
    std::string comment; // one or more lines, written as // comments above the table
    std::vector<double> values;
};

void writeTablesHeader(std::ostream& out, int size, const std::vector<NamedTable>& tables);

} // namespace vkpt::tables
