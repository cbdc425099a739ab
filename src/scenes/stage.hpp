#pragma once
// The stages a scene needs, as objects. inspect() says run, cached or skipped and why without doing
// the work; resolve() does it once before the ensemble (builds or loads a table). `rollspec plan`
// prints inspect(), and `rollspec run` resolves through the same inspection (CachedTable::resolve
// inspects first), so the two cannot disagree. Per-realisation stages (texture, dynamics, spectra)
// run inside the ensemble and resolve nothing here.
#include <functional>
#include <memory>
#include <string>

#include "src/stiffness/cached_table.hpp"

namespace rollspec::scenes {

enum class StageStatus { run, cached, skipped };

struct StagePlan {
  std::string stage;  // texture, surface, stiffness_table, blocked_force, force, dynamics, spectra
  StageStatus status;
  std::string reason;
  bool table = false;  // a cached table shared by all realisations (a TableStage's inspection)
  std::string path{};  // a table stage's file, where the study's [stiffness] table puts it
};

const char* status_name(StageStatus s);

class Stage {
 public:
  virtual ~Stage() = default;
  virtual StagePlan inspect() const = 0;
  virtual void resolve(bool /*rebuild*/, bool /*quiet*/) {}
};

// A stage whose status the study fixes (per-realisation work, or not needed).
class FixedStage final : public Stage {
 public:
  explicit FixedStage(StagePlan plan) : plan_(std::move(plan)) {}
  StagePlan inspect() const override { return plan_; }

 private:
  StagePlan plan_;
};

// A cached table shared by all realisations: cached when a valid table is stored, run when none
// is, run but refused unless --rebuild when a mismatched or damaged one is. resolve() builds or
// loads it and hands it to `use` with the status ("cached <path>" / "built <path>"). `detail`, if
// any, follows the plan's reason (e.g. the grid a stage derived for its table).
class TableStage final : public Stage {
 public:
  using Make = std::function<std::unique_ptr<stiffness::TableData>()>;
  using Build = std::function<void(stiffness::TableData&, bool quiet)>;
  using Use = std::function<void(const stiffness::TableData&, const std::string& status, bool quiet)>;
  TableStage(std::string name, stiffness::CachedTable table, Make make, Build build, Use use, std::string detail = "");
  StagePlan inspect() const override;
  void resolve(bool rebuild, bool quiet) override;
  // Missing, valid or mismatched now (a stage that lives inside the table, e.g. its surfaces, asks).
  stiffness::TableState state() const;

 private:
  std::string name_;
  stiffness::CachedTable table_;
  Make make_;
  Build build_;
  Use use_;
  std::string detail_;
};

// A stage whose status follows another stage's inspection at plan time.
class DerivedStage final : public Stage {
 public:
  explicit DerivedStage(std::function<StagePlan()> plan) : plan_(std::move(plan)) {}
  StagePlan inspect() const override { return plan_(); }

 private:
  std::function<StagePlan()> plan_;
};

}  // namespace rollspec::scenes
