// vigil-eval: `vigil eval` as an executable of its own, linking only the evaluation library and core/
// (app/eval_command.h). Same arguments, output, messages and exit statuses as `vigil eval`.
#include <cstdio>
#include <exception>

#include "app/eval_command.h"
#include "core/error.h"

int main(int argc, char** argv) {
  using namespace vigil::app;
  CLI::App app{kEvalDescription, "vigil-eval"};
  app.set_version_flag("--version", "vigil-eval 0.1.0");
  EvalArgs args;
  AddEvalOptions(&app, &args);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "vigil: error: %s\n", vigil::OneLine(e.what()).c_str());
    return 2;
  }
  try {
    return RunEval(args);
  } catch (const vigil::InputError& e) {
    std::fprintf(stderr, "vigil: error: %s\n", e.what());  // already one line
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vigil: error: %s\n", vigil::OneLine(e.what()).c_str());
    return 1;
  }
}
