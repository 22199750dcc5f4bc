// JSON output shared by the writers and the readers' messages
// (json_write.hpp).

#include "io/json_write.hpp"

#include <nlohmann/json.hpp>

namespace breakshot::json_io {

std::string format_number(double v) { return nlohmann::json(v).dump(); }

}  // namespace breakshot::json_io
