// `vigil config`: prints the fully resolved configuration, or the documentation of every key.
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "experiments/runs/run_config.h"

namespace vigil::app {

void AddConfigCommand(CLI::App& root) {
  auto* cmd = root.add_subcommand("config", "print the resolved configuration (defaults + CONFIG + --set)");
  struct Args {
    ConfigArgs config;
    bool keys = false;
  };
  auto args = std::make_shared<Args>();  // outlives parsing: owned by the action
  args->config.AddTo(cmd, /*optional=*/true);
  cmd->add_flag("--keys", args->keys, "print a Markdown table of every config key instead");
  SetAction(cmd, [args] {
    experiments::RunConfig config =
        experiments::LoadRunConfig(args->config.config_path, args->config.AllOverrides());
    const std::string text =
        args->keys ? config::KeysMarkdownTable(config::DescribeKeys(config)) : config::ToYaml(config);
    std::fputs(text.c_str(), stdout);
    return 0;
  });
}

}  // namespace vigil::app
