// alarm: the engine alarms exactly where the documented checks require it — it must not plan a
// shape the rules forbid, nor alarm on one they allow. One comparison, two oracles: `alarm` for the
// FANUC-dialect programs, `siemens-alarm` for the SINUMERIK ones (LCYC95.ALARMS: 61002, 61610, 10931
// read from the program, harness/judge/siemens_reading.h), each citing its own rules.
#include <sstream>

#include "oracles/oracles.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

class AlarmOracle : public Oracle {
 public:
  AlarmOracle(std::string id, std::vector<std::string> rules, bool siemens)
      : id_(std::move(id)), rules_(std::move(rules)), siemens_(siemens) {}
  std::string id() const override { return id_; }
  std::vector<std::string> rules() const override { return rules_; }
  // `alarm` judges G74.1 too: the alarms of docs/g74_1.md I6b read from the program
  // (oracles/groove/groove_spec.h: the ranges, missing words and blocks, words the blocks do not
  // take, P/Q's decimal point, a groove the tool cannot cut).
  bool judges(CycleFamily f) const override { return isSiemensFamily(f) == siemens_; }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    if (in.program.siemensFamily.has_value() != siemens_) return;  // the other dialect's oracle judges it
    const std::optional<Alarm> expected = in.program.firstAlarm();
    const std::optional<Alarm>& got = in.path.alarm;
    if (expected && !got) {
      std::ostringstream m;
      m << "the engine planned what the rules forbid: expected alarm " << expected->code << " at line " << expected->line
        << " (" << expected->message << ")";
      out.push_back(finding(*this, std::nullopt, m.str()));
    } else if (expected) {
      // FANUC codes compared exactly; an engine's own codes on the line only (alarms.h).
      if (auto why = alarmMismatch(expected->code, expected->line, *got)) out.push_back(finding(*this, std::nullopt, *why));
    } else if (!expected && got) {
      out.push_back(finding(*this, std::nullopt,
                            "the engine alarmed (" + got->code + " at line " + std::to_string(got->line) +
                                ") on cycles the documented checks allow"));
    }
  }

 private:
  std::string id_;
  std::vector<std::string> rules_;
  bool siemens_;
};

}  // namespace

std::unique_ptr<Oracle> makeAlarmOracle() {
  return std::make_unique<AlarmOracle>(
      "alarm",
      std::vector<std::string>{"G71.T1.ALARM", "G71.T2.MONO", "G72.T1.MONO", "G71.HEAD.G0G1", "G71.HEAD.NOX",
                               "G71.LIMIT.HEIGHT", "G72.RANGE", "G73.ALARMS", "G73.D.RANGE", "G73.FS10.FMT", "G73.HEAD",
                               "G74_1.FMT", "G74_1.RANGE", "PROG.SIGN"},
      false);
}

std::unique_ptr<Oracle> makeSiemensAlarmOracle() {
  return std::make_unique<AlarmOracle>("siemens-alarm", std::vector<std::string>{"LCYC95.ALARMS", "LCYC95.PARAMS", "LCYC95.CONTOUR", "SIEMENS.FEED"},
                                       true);
}

}  // namespace cyclecert
