// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The code in the manuals is compiled: every ```cpp block of doc/*/*.md must be preceded by a line
//   <!-- snippet: examples/Some_package/some_example.cpp -->
// and be identical to that file, which the build compiles and the tests run. A block may also be
// an excerpt: <!-- snippet: FILE lines A-B --> (1-based, inclusive).
//
// usage: doc_snippets_check PROJECT_SOURCE_DIR

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::vector<std::string> read_lines(const fs::path& path)
{
  std::ifstream in(path);
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: doc_snippets_check PROJECT_SOURCE_DIR\n";
    return 2;
  }
  const fs::path root = argv[1];
  const std::regex marker(R"(^<!-- snippet: (\S+)( lines ([0-9]+)-([0-9]+))? -->\s*$)");
  std::size_t checked = 0, failures = 0;
  std::vector<fs::path> manuals;
  for(const auto& entry : fs::recursive_directory_iterator(root / "doc"))
    if(entry.path().extension() == ".md")
      manuals.push_back(entry.path());
  for(const fs::path& manual : manuals)
  {
    const std::vector<std::string> lines = read_lines(manual);
    for(std::size_t i = 0; i < lines.size(); ++i)
    {
      if(lines[i].rfind("```cpp", 0) != 0)
        continue;
      const std::string where = manual.lexically_relative(root).string() + ":" + std::to_string(i + 1);
      std::smatch m;
      std::size_t k = i; // the marker is the closest non-empty line above the block
      while(k > 0 && lines[k - 1].empty())
        --k;
      if(k == 0 || !std::regex_match(lines[k - 1], m, marker))
      {
        std::cerr << where << ": a ```cpp block without a <!-- snippet: FILE --> line above it\n";
        ++failures;
        continue;
      }
      std::vector<std::string> block;
      std::size_t j = i + 1;
      for(; j < lines.size() && lines[j].rfind("```", 0) != 0; ++j)
        block.push_back(lines[j]);
      const std::vector<std::string> whole = read_lines(root / m[1].str());
      std::vector<std::string> file = whole;
      if(file.empty())
      {
        std::cerr << where << ": " << m[1].str() << " does not exist or is empty\n";
        ++failures;
        continue;
      }
      if(m[2].matched)
      {
        const std::size_t a = std::stoul(m[3].str()), b = std::stoul(m[4].str());
        if(a < 1 || b < a || b > file.size())
        {
          std::cerr << where << ": lines " << a << "-" << b << " are not in " << m[1].str() << "\n";
          ++failures;
          continue;
        }
        file = std::vector<std::string>(file.begin() + std::ptrdiff_t(a - 1), file.begin() + std::ptrdiff_t(b));
      }
      if(block != file)
      {
        std::size_t d = 0;
        while(d < block.size() && d < file.size() && block[d] == file[d])
          ++d;
        std::cerr << where << ": the block differs from " << m[1].str() << m[2].str() << " at its line " << d + 1
                  << ":\n  manual: " << (d < block.size() ? block[d] : "<end>")
                  << "\n  file:   " << (d < file.size() ? file[d] : "<end>") << "\n";
        // the usual cause, an edit above the lines: where the block is now, if it is there once
        std::size_t found = 0, at = 0;
        for(std::size_t s = 0; m[2].matched && !block.empty() && s + block.size() <= whole.size(); ++s)
          if(std::equal(block.begin(), block.end(), whole.begin() + std::ptrdiff_t(s)))
            ++found, at = s;
        if(found == 1)
          std::cerr << "  the block is lines " << at + 1 << "-" << at + block.size() << " of the file now: update the "
                    << "snippet line\n";
        ++failures;
      }
      ++checked;
      i = j;
    }
  }
  std::cout << checked << " code blocks checked in " << manuals.size() << " manuals, " << failures
            << " problems\n";
  return failures == 0 && checked > 0 ? 0 : 1;
}
