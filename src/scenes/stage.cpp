#include "src/scenes/stage.hpp"

namespace rollspec::scenes {

const char* status_name(StageStatus s) {
  switch (s) {
    case StageStatus::run:
      return "run";
    case StageStatus::cached:
      return "cached";
    case StageStatus::skipped:
      return "skipped";
  }
  return "?";
}

TableStage::TableStage(std::string name, stiffness::CachedTable table, Make make, Build build, Use use,
                       std::string detail)
    : name_(std::move(name)),
      table_(std::move(table)),
      make_(std::move(make)),
      build_(std::move(build)),
      use_(std::move(use)),
      detail_(std::move(detail)) {}

stiffness::TableState TableStage::state() const {
  std::string why;
  const auto scratch = make_();
  return table_.inspect(*scratch, why);
}

StagePlan TableStage::inspect() const {
  std::string why;
  const auto scratch = make_();
  const stiffness::TableState state = table_.inspect(*scratch, why);
  return {name_, state == stiffness::TableState::valid ? StageStatus::cached : StageStatus::run,
          stiffness::table_plan_reason(table_, state, why) + (detail_.empty() ? "" : "; " + detail_), true,
          table_.path()};
}

void TableStage::resolve(bool rebuild, bool quiet) {
  const auto data = make_();
  std::string status;
  table_.resolve(
      *data, rebuild, [&](stiffness::TableData& t) { build_(t, quiet); }, status);
  use_(*data, status, quiet);
}

}  // namespace rollspec::scenes
