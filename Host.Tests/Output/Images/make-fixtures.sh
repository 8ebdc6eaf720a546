#!/bin/sh
# Rebuilds the image fixtures of ImageReaderTests from the two text sources beside this script, with
# ImageMagick 6 (Debian package imagemagick): the sources hold the pixel values the tests expect.
#   levels.ppm  8x6, 16 bits per channel: pixel (x, y) = (8191 x, 13107 y, 4369 (x + y))
#   blocks.ppm  8x6, 8 bits: 2x2 blocks whose channels are each 0 or 255
set -e
cd "$(dirname "$0")"
im=/usr/bin/convert
$im levels.ppm -strip -depth 16 PNG48:levels-16bit.png
$im levels.ppm -strip -depth 8 -interlace PNG PNG24:levels-interlaced.png
$im levels.ppm -strip -depth 8 -colors 256 +dither PNG8:levels-palette.png
$im levels.ppm -strip -depth 8 -alpha set -channel A -evaluate set 50% +channel PNG32:levels-alpha.png
$im levels.ppm -strip -depth 8 -quality 95 -sampling-factor 1x1 levels.jpg
$im levels.ppm -strip -depth 8 -define webp:lossless=true levels.webp
$im levels.ppm -strip -depth 8 BMP3:levels.bmp
$im levels.ppm -strip -depth 8 +dither levels.gif
$im blocks.ppm -strip -depth 16 PNG48:blocks-16bit.png
$im blocks.ppm -strip -quality 95 -sampling-factor 1x1 blocks.jpg
$im blocks.ppm -strip -interlace PNG PNG8:blocks-palette-interlaced.png
