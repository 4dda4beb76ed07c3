// Generates docs/validation.md from what the repository holds as data, so that no measured
// number is typed into the document: `valsalva docs-validation > docs/validation.md` calls it
// and tests/validation/test_validation_docs.cpp checks the committed copy.
//
// The document: the introduction (validation/README.md), a summary table with one row per
// stored record (validation/<case>/results/{full,quick}.json, validation/record.hpp; a case
// without any has a "not measured" row), then one section per case in name order: the case's
// description, its README.md (validation/<case>/README.md) with the results of its records at
// the README's line `<!-- results -->` (after the text when it has none), and last the notes
// that belong to no case (validation/notes/*.md, in name order).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace valsalva::validation {

struct CaseDoc {
  std::string name;
  std::string description;
};

// The registered cases (all_cases()) in name order.
std::vector<CaseDoc> registered_case_docs();

// `validation_dir`: the validation folder of the source tree (or of an installed copy).
void write_validation_docs(std::ostream& out, const std::filesystem::path& validation_dir,
                           std::vector<CaseDoc> cases);

}  // namespace valsalva::validation
