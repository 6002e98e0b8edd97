// sphtroch completion bash|zsh — a shell completion script written from the tool's own registry of
// commands and options (every command registered before this one, so nothing is listed by hand):
//   source <(sphtroch completion bash)         # or save it as
//                                               # /usr/share/bash-completion/completions/sphtroch
//   source <(sphtroch completion zsh)          # zsh, through its bashcompinit
// The script holds two tables keyed by the command path ("sphtroch", "sphtroch synth", "sphtroch
// synth fit", ...): its subcommands and its long options. It walks the words typed so far down the
// subcommands, then offers that command's subcommands and options; other words (values, files)
// fall back to the shell's file names (`complete -o default`).
#include "cli_common.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sphtroch::cli {

namespace {

struct CommandEntry {
  std::string path;                      // "sphtroch", "sphtroch synth fit" (bash keys are never empty)
  std::vector<std::string> subcommands;  // names
  std::vector<std::string> options;      // --long names, --help first
};

void collect(const CLI::App& app, const std::string& path, std::vector<CommandEntry>& out) {
  CommandEntry e{path, {}, {"--help"}};
  for (const CLI::Option* opt : app.get_options())
    for (const std::string& name : opt->get_lnames())
      if (name != "help") e.options.push_back("--" + name);
  const std::vector<const CLI::App*> subs = app.get_subcommands([](const CLI::App*) { return true; });
  for (const CLI::App* sub : subs) e.subcommands.push_back(sub->get_name());
  out.push_back(e);
  for (const CLI::App* sub : subs) collect(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), out);
}

std::string words(const std::vector<std::string>& list) {
  std::string s;
  for (const std::string& w : list) s += (s.empty() ? "" : " ") + w;
  return s;
}

std::string bash_script(const CLI::App& app) {
  std::vector<CommandEntry> entries;
  collect(app, "sphtroch", entries);
  std::string s = "# bash completion for sphtroch, written by `sphtroch completion bash` from the tool's registry\n";
  s += "declare -gA _sphtroch_subcommands=(";
  for (const CommandEntry& e : entries) s += " [\"" + e.path + "\"]=\"" + words(e.subcommands) + "\"";
  s += " )\ndeclare -gA _sphtroch_options=(";
  for (const CommandEntry& e : entries) s += " [\"" + e.path + "\"]=\"" + words(e.options) + "\"";
  s += " )\n"
       "_sphtroch() {\n"
       "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" path=sphtroch word i\n"
       "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
       "    word=\"${COMP_WORDS[i]}\"\n"
       "    case \" ${_sphtroch_subcommands[$path]} \" in *\" $word \"*) path=\"$path $word\" ;; esac\n"
       "  done\n"
       "  COMPREPLY=($(compgen -W \"${_sphtroch_subcommands[$path]} ${_sphtroch_options[$path]}\" -- \"$cur\"))\n"
       "}\n"
       "complete -o default -F _sphtroch sphtroch\n";
  return s;
}

}  // namespace

void register_completion(CLI::App& app, std::vector<std::pair<CLI::App*, Action>>& actions) {
  auto shell = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("completion", "print a bash or zsh completion script for sphtroch (from its own commands and options)");
  cmd->add_option("shell", *shell, "bash or zsh")->type_name("SHELL")->required()->check(CLI::IsMember({"bash", "zsh"}));
  cmd->footer("Example: source <(sphtroch completion bash)");
  actions.emplace_back(cmd, [shell, &app] {
    const std::string script = bash_script(app);
    std::cout << (*shell == "zsh" ? "# zsh: through bashcompinit\nautoload -U +X bashcompinit && bashcompinit\n" : "") << script;
    if (!std::cout.flush()) throw UsageError{"completion: the script could not be written to stdout"};
  });
}

}  // namespace sphtroch::cli
