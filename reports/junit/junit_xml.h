#pragma once
// junit.xml for CI from report.json's document (reports/README.md), in the JUnit dialect Jenkins
// and GitLab read (validated against jenkinsci's junit-10.xsd in the tests): one <testsuite> per
// engine, one <testcase> per spec or regression case and per generated case that failed, with
//   classname  "<engine>.<kind>.<cycle>" ("<engine>.fuzz" for generated cases; dots in the engine's
//              name become '_', since CI splits a classname at its last dot into package and class),
//   name       the case id,
//   <failure>  for a failing case: the rules it fails and its detail in the message, the findings,
//              the command that reproduces it and (generated cases) the program in the text,
//   <error>    for an engine failure, <skipped> for a case the engine cannot express,
// and the engine's version, the suite's identity and the fuzz campaign's counts as properties.
#include <string>

#include <nlohmann/json.hpp>

namespace cyclecert {

std::string junitXml(const nlohmann::json& report);

}  // namespace cyclecert
