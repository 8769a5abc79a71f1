#ifndef Commands_h
#define Commands_h

#include "CommandLine.h"

namespace cli
{

/// `silhouette smooth`: read, smooth, optionally write, print the figures.
void RunSmooth(const SmoothOptions& options);

/// `silhouette render`: read, smooth, render to PNG, print the figures.
void RunRender(const RenderOptions& options);

} // namespace cli

#endif
