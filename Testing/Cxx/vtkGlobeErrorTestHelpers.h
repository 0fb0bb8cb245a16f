// Helpers for tests that watch what VTK objects report and how often algorithms run, and the
// time-series tests' shared set-up.
#ifndef vtkGlobeErrorTestHelpers_h
#define vtkGlobeErrorTestHelpers_h

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkGlobeRasterReader.h"
#include "vtkNew.h"
#include "vtkTestErrorObserver.h"

#include <cstdio>
#include <string>
#include <vector>

namespace vtkGlobeTest
{
/**
 * True when the last error contains every one of the words; prints the message from `from`
 * on (vtkErrorMacro's text starts with the source location) and clears the observer.
 */
inline bool ErrorSaid(vtkTest::ErrorObserver* observer, const std::vector<std::string>& words,
  const char* from = "Cannot")
{
  const std::string message = observer->GetError() ? observer->GetErrorMessage() : "";
  bool said = !message.empty();
  for (const std::string& w : words)
  {
    said = said && message.find(w) != std::string::npos;
  }
  const size_t start = message.find(from);
  std::string shown = message.empty() ? "(nothing)"
                                      : message.substr(start == std::string::npos ? 0 : start);
  while (!shown.empty() && (shown.back() == '\n' || shown.back() == ' '))
  {
    shown.pop_back();
  }
  std::printf("       error: %s\n", shown.c_str());
  observer->Clear();
  return said;
}

/// Counts an algorithm's executions (its EndEvents).
struct ExecutionCounter
{
  int Count = 0;
  vtkNew<vtkCallbackCommand> Command;
  explicit ExecutionCounter(vtkAlgorithm* algorithm)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
      ++static_cast<ExecutionCounter*>(self)->Count;
    });
    algorithm->AddObserver(vtkCommand::EndEvent, this->Command);
  }
};

/// The series tests' step times (decimal years).
constexpr double SeriesTimes[3] = { 2026.0, 2026.25, 2026.5 };

/// A reader given the three step files out of order, each with its SeriesTimes entry (the
/// reader must sort them).
inline void AddSeriesOutOfOrder(vtkGlobeRasterReader* reader, const std::string (&steps)[3])
{
  reader->AddFileName(steps[2].c_str(), SeriesTimes[2]);
  reader->AddFileName(steps[0].c_str(), SeriesTimes[0]);
  reader->AddFileName(steps[1].c_str(), SeriesTimes[1]);
}
} // namespace vtkGlobeTest

#endif
