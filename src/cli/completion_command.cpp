/// @file completion_command.cpp
/// `fsweep completion bash`: a bash completion script made by walking the command tree CLI11 holds
/// (Debian's CLI11 2.1 has no generator of its own): the subcommands after `fsweep`, each one's
/// long and short options after it, files elsewhere. `cmake --install` installs its output as
/// share/bash-completion/completions/fsweep.

#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "cli/commands.hpp"

namespace fsweep::cli {
namespace {

/// The options of `app` as completion words: --long and -s names, space-separated.
std::string option_words(const CLI::App& app) {
  std::string words;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) words += " --" + l;
    for (const std::string& s : o->get_snames()) words += " -" + s;
  }
  return words;
}

/// The script: one case per subcommand.
std::string bash_script(const CLI::App& app) {
  std::ostringstream out;
  std::string commands;
  const auto subs = app.get_subcommands([](const CLI::App* a) { return !a->get_name().empty(); });
  for (const CLI::App* s : subs) commands += (commands.empty() ? "" : " ") + s->get_name();
  out << "# bash completion for fsweep (made by `fsweep completion bash`)\n"
         "_fsweep() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]}\n"
         "  if [ \"$COMP_CWORD\" -eq 1 ]; then\n"
         "    COMPREPLY=($(compgen -W \""
      << commands << option_words(app)
      << "\" -- \"$cur\"))\n"
         "    return\n"
         "  fi\n"
         "  local opts=\"\"\n"
         "  case \"${COMP_WORDS[1]}\" in\n";
  for (const CLI::App* s : subs)
    out << "    " << s->get_name() << ") opts=\"" << option_words(*s) << "\" ;;\n";
  out << "  esac\n"
         "  if [[ $cur == -* ]]; then\n"
         "    COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
         "  else\n"
         "    COMPREPLY=($(compgen -f -- \"$cur\"))\n"
         "  fi\n"
         "}\n"
         "complete -o filenames -F _fsweep fsweep\n";
  return out.str();
}

}  // namespace

Command add_completion_command(CLI::App& app) {
  auto shell = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "completion", "Print a shell completion script (bash) for fsweep's commands and options");
  sub->add_option("SHELL", *shell, "The shell: bash")->required()->check(CLI::IsMember({"bash"}));
  return [&app, shell] {  // shell: the option writes there, so it lives as long as the command
    std::cout << bash_script(app);
    return 0;
  };
}

}  // namespace fsweep::cli
