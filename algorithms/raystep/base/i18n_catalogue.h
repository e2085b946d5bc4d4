#pragma once
// Every language's files (i18n/<code>/*.json) as embedded in raystep_i18n (generated table;
// base/i18n.cpp).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// The text of an embedded catalogue file by its path under i18n/ ("it/core.json").
std::optional<std::string_view> embeddedCatalogue(std::string_view name);
/// The embedded catalogue files' names, sorted.
std::vector<std::string> embeddedCatalogueNames();

}  // namespace raystep
