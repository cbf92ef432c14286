// SPDX-License-Identifier: GPL-3.0-or-later
// main() of every GoogleTest binary: the C library takes the locale of the environment (LC_ALL,
// LANG), as the GUI does (QApplication calls setlocale), so that scripts/test's second run under
// LC_ALL=de_DE.UTF-8 really runs core and CLI tests with a comma as the decimal point. With
// AXISTUNE_REQUIRE_LOCALE=1 a locale that is not installed fails the run instead of falling back to C.
#include <clocale>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    if (!std::setlocale(LC_ALL, "")) {
        const char* require = std::getenv("AXISTUNE_REQUIRE_LOCALE");
        std::fprintf(stderr,
                     "warning: the locale of the environment (LC_ALL/LANG) is not installed; running under C\n");
        if (require && std::strcmp(require, "1") == 0)
            return 1;
    }
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
