#include "render/huge_page_allocator.h"

#include <cstdint>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "render/image.h"

namespace rugosim {
namespace {

// The VmFlags line of the mapping holding `address`, from /proc/self/smaps ("" if none).
std::string vm_flags_at(const void* address) {
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t start = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> start >> dash >> end && dash == '-') {
      inside = start <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

TEST(HugePageAllocator, AFrameSizedBufferIsAlignedAdvisedAndWholeEndToEnd) {
  if (!huge_pages::kMapsLargeBuffers) GTEST_SKIP() << "operator new under the sanitizers";
  const std::size_t bytes = Image::bytes(3840, 2160);  // 33 MB, not a multiple of 2 MB
  Image image(3840, 2160);
  ASSERT_EQ(image.rgba.size(), bytes);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(image.rgba.data()) % huge_pages::kHugePage, 0u);
  // Advised for huge pages ("hg"), whatever the kernel then does with the advice.
  EXPECT_NE(vm_flags_at(image.rgba.data()).find(" hg"), std::string::npos)
      << vm_flags_at(image.rgba.data());
  // Zeroed on allocation and writable to the last byte.
  EXPECT_EQ(std::accumulate(image.rgba.begin(), image.rgba.end(), std::uint64_t{0}), 0u);
  for (std::size_t i = 0; i < bytes; i += 4096)
    image.rgba[i] = static_cast<std::uint8_t>(i >> 12);
  image.rgba.back() = 7;
  const Image copy = image;
  EXPECT_NE(copy.rgba.data(), image.rgba.data());
  EXPECT_TRUE(copy.rgba == image.rgba);
}

TEST(HugePageAllocator, SmallAndBoundarySizesRoundTrip) {
  for (const std::size_t bytes :
       {std::size_t{1}, std::size_t{4096}, huge_pages::kHugePageMinimum - 1,
        huge_pages::kHugePageMinimum, huge_pages::kHugePageMinimum + 1, std::size_t{6} << 20}) {
    HugePageAllocator<std::uint8_t> allocator;
    std::uint8_t* buffer = allocator.allocate(bytes);
    ASSERT_NE(buffer, nullptr) << bytes;
    buffer[bytes - 1] = 2;
    buffer[0] = 1;  // the same byte when bytes is 1
    EXPECT_EQ(buffer[bytes - 1], bytes == 1 ? 1 : 2) << bytes;
    allocator.deallocate(buffer, bytes);
  }
}

TEST(HugePageAllocator, ARefusedSizeThrowsBadAlloc) {
  HugePageAllocator<std::uint32_t> allocator;
  EXPECT_THROW(static_cast<void>(allocator.allocate(static_cast<std::size_t>(-1) / 2)),
               std::bad_alloc);
}

}  // namespace
}  // namespace rugosim
