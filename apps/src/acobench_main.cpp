// acobench: the benchmark harness (issue 7 builds the grid; this is its entry point).
#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App cli{"acobench sweeps algorithms, alpha, beta, ants and threads over instances and writes one CSV row per run.",
               "acobench"};
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return cli.exit(e);
  }
  std::cout << cli.help();
  return 0;
}
