// Reading a game record file for the measuring tools of bench/ (not part
// of the library): the file's text through read_record, or a message on
// stderr that names the tool, the file and what is wrong.
#pragma once

#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <variant>

#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"

namespace bench_tools {

inline std::optional<breakshot::GameRecord> read_record_file(const char* tool, const char* path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "%s: cannot read %s\n", tool, path);
    return std::nullopt;
  }
  std::stringstream text;
  text << in.rdbuf();
  auto read = breakshot::read_record(text.str());
  if (const auto* err = std::get_if<breakshot::RecordError>(&read)) {
    std::fprintf(stderr, "%s: %s: %s: %s\n", tool, path, err->path.c_str(), err->reason.c_str());
    return std::nullopt;
  }
  return std::get<breakshot::GameRecord>(std::move(read));
}

}  // namespace bench_tools
