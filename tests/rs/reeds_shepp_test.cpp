#include "rs/reeds_shepp.h"
#include <gtest/gtest.h>
TEST(Rs, Placeholder) { EXPECT_EQ(hrs::rs::kWordCount, 48); }
