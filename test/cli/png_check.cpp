// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Decodes a picture of geodesic_ridge --png with libpng (a real decoder, not
// ours) and checks it: its size, and that it shows something (the red ridge,
// the green source, the white background and many colours in all). It prints
// the number of grey pixels too: the parts the source cannot reach.
//
//   png_check FILE.png WIDTH HEIGHT [OUT.ppm]
//
// OUT.ppm receives the decoded pixels, to compare two pictures byte for byte.
#include <png.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  if(argc != 4 && argc != 5)
  {
    std::cerr << "usage: png_check FILE.png WIDTH HEIGHT [OUT.ppm]\n";
    return 2;
  }
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  if(!png_image_begin_read_from_file(&image, argv[1]))
  {
    std::cerr << argv[1] << ": not a PNG libpng reads: " << image.message << "\n";
    return 1;
  }
  image.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> rgb(PNG_IMAGE_SIZE(image));
  if(!png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr))
  {
    std::cerr << argv[1] << ": libpng cannot decode it: " << image.message << "\n";
    return 1;
  }
  const unsigned long w = image.width, h = image.height;
  if(w != std::strtoul(argv[2], nullptr, 10) || h != std::strtoul(argv[3], nullptr, 10))
  {
    std::cerr << argv[1] << ": " << w << " x " << h << " pixels, expected " << argv[2] << " x " << argv[3] << "\n";
    return 1;
  }
  std::set<unsigned long> colours;
  std::size_t red = 0, green = 0, white = 0, grey = 0;
  for(std::size_t i = 0; i < rgb.size(); i += 3)
  {
    const unsigned char r = rgb[i], g = rgb[i + 1], b = rgb[i + 2];
    colours.insert((unsigned long)r << 16 | (unsigned long)g << 8 | b);
    red += r == 220 && g == 30 && b == 30;   // Png_curves' default: the ridge
    green += r == 20 && g == 170 && b == 40; // the source's cross
    white += r == 255 && g == 255 && b == 255;
    grey += r == g && b == (g < 243 ? g + 12 : 255) && g < 255; // the unreachable parts' shaded grey
  }
  std::cout << argv[1] << ": " << w << " x " << h << ", " << colours.size() << " colours, " << red << " ridge, "
            << green << " source, " << white << " background and " << grey << " grey pixels\n";
  if(red < 100 || green == 0 || white == 0 || colours.size() < 50)
  {
    std::cerr << argv[1] << ": the picture lacks the ridge, the source, the background or colours\n";
    return 1;
  }
  if(argc == 5)
  {
    std::ofstream os(argv[4], std::ios::binary);
    os << "P6\n" << w << ' ' << h << "\n255\n";
    os.write(reinterpret_cast<const char*>(rgb.data()), static_cast<std::streamsize>(rgb.size()));
    if(!os) { std::cerr << "cannot write " << argv[4] << "\n"; return 1; }
  }
  return 0;
}
