// The help texts of the commands this file parses: the program's main help
// and those of smooth, render, generate and view (simplify, compare and
// figure keep theirs beside their code). What `silhouette help COMMAND` and
// `COMMAND --help` print.
#ifndef CommandHelp_h
#define CommandHelp_h

#include <string>

namespace cli
{

std::string MainHelp();
std::string FiguresHelp();
std::string SmoothHelp();
std::string RenderHelp();
std::string GenerateHelp();
std::string ViewHelp();

} // namespace cli

#endif
