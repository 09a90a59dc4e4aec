// SPDX-License-Identifier: GPL-3.0-or-later
/// @file main.cpp
/// @brief The `dfchaos` command-line tool (see app.cpp and `dfchaos --help`).
#include "cli.hpp"

int main(int argc, char** argv) { return dfchaos::cli::run(argc, argv); }
