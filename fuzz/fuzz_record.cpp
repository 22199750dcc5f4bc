// libFuzzer entry point for game records: any bytes go to read_record();
// a record it accepts must write back to text that reads back equal, and
// replays (its first actions) without a crash, a hang or a sanitizer
// report. replay() never throws: whatever the record claims, it answers
// identical or names a difference.
//
// Build and run:  cmake --preset fuzz && cmake --build --preset fuzz
//                 build/fuzz/fuzz/breakshot_fuzz_record CORPUS_DIR fuzz/record_corpus
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include "breakshot/record.hpp"
#include "breakshot/record_io.hpp"

namespace {

// Replaying simulates every shot; a few keep one input fast.
constexpr std::size_t kMaxActions = 12;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "breakshot_fuzz_record: check failed: %s\n", what);
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto parsed = breakshot::read_record(text);
  if (std::holds_alternative<breakshot::RecordError>(parsed)) {
    check(!std::get<breakshot::RecordError>(parsed).reason.empty(), "an error gives a reason");
    return 0;
  }
  breakshot::GameRecord record = std::get<breakshot::GameRecord>(std::move(parsed));
  // read_record accepts finite numbers only, so writing cannot refuse.
  const std::string again = breakshot::write_record(record);
  auto back = breakshot::read_record(again);
  check(std::holds_alternative<breakshot::GameRecord>(back), "a written record reads back");
  check(std::get<breakshot::GameRecord>(back) == record, "and reads back equal");
  if (record.actions.size() > kMaxActions) record.actions.resize(kMaxActions);
  const breakshot::ReplayReport report = breakshot::replay(record);
  check(report.identical || !report.message.empty(), "a difference is named");
  return 0;
}
