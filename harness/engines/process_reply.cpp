#include "harness/engines/process_reply.h"

#include "reference/model/toolpath_json.h"

namespace cyclecert {

nlohmann::json parseProcessReply(const std::string& line, long request) {
  return parseJsonDocument(line, "the reply to request " + std::to_string(request));
}

EngineResult processReplyResult(const nlohmann::json& reply) {
  try {
    if (reply.contains("toolpath")) return EngineResult::planned(toolpathFromJson(reply["toolpath"]));
    if (reply.contains("alarm")) {
      Toolpath t;
      t.alarm = alarmFromJson(reply["alarm"], "/alarm");
      return EngineResult::planned(std::move(t));
    }
    if (reply.contains("not_applicable")) return EngineResult::notApplicable(reply["not_applicable"].dump());
    if (reply.contains("error")) return EngineResult::failed("the engine reported: " + reply["error"].dump());
  } catch (const std::exception& e) {
    return EngineResult::failed(std::string("reply: ") + e.what());
  }
  return EngineResult::failed("a reply with none of toolpath, alarm, not_applicable, error");
}

}  // namespace cyclecert
