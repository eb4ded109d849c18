#pragma once
// The pieces of the animation page, embedded at build time: web/build.mjs bundles three.js,
// uPlot and web/src/animation.js with esbuild and writes them into a generated source (CMake
// runs it when web/src or web/package-lock.json changes). Each piece is a list of chunks to be
// written one after the other.
#include <span>
#include <string_view>

namespace tumble::animation_assets {

std::span<const std::string_view> script();  // one IIFE: contains no "</script"
std::span<const std::string_view> style();   // uPlot's style sheet, then the page's
std::span<const std::string_view> markup();  // the body's markup before the data and script

}  // namespace tumble::animation_assets
