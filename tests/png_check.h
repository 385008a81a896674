/* A small PNG reader for tests: enough of the format (8-bit greyscale, RGB, RGBA and
 * palette images, not interlaced) to decode what gnuplot's png and pngcairo terminals
 * write, so that a test can say a plot is not blank and that a curve's colour is in it.
 * Uses zlib for the compressed image data. */
#ifndef RS_TESTS_PNG_CHECK_H
#define RS_TESTS_PNG_CHECK_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "check.h"

typedef struct png_image {
  uint32_t width, height;
  uint32_t *rgb; /* 0xRRGGBB per pixel, row by row; alpha composited over white */
} png_image;

static inline uint32_t png_be32(const unsigned char *p)
{
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static inline int png_paeth(int a, int b, int c)
{
  int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Reverses the per-row filters in place (rows of `stride` bytes after a filter byte). */
static inline int png_unfilter(unsigned char *raw, uint32_t h, size_t stride, int bpp)
{
  unsigned char *prev = NULL;
  for (uint32_t y = 0; y < h; ++y) {
    unsigned char *row = raw + y * (stride + 1);
    int f = row[0];
    unsigned char *px = row + 1;
    for (size_t i = 0; i < stride; ++i) {
      int a = i >= (size_t)bpp ? px[i - bpp] : 0, b = prev ? prev[i] : 0;
      int c = prev && i >= (size_t)bpp ? prev[i - bpp] : 0;
      int add = f == 0   ? 0
                : f == 1 ? a
                : f == 2 ? b
                : f == 3 ? (a + b) / 2
                : f == 4 ? png_paeth(a, b, c)
                         : -1;
      if (add < 0) return -1;
      px[i] = (unsigned char)(px[i] + add);
    }
    prev = px;
  }
  return 0;
}

/* Decodes `path`; returns 0 and fills img (free img->rgb), or -1 with a reason on stderr. */
static inline int png_read(const char *path, png_image *img)
{
  memset(img, 0, sizeof *img);
  FILE *f = fopen(path, "rb");
  if (!f) {
    fprintf(stderr, "png_read: cannot open %s\n", path);
    return -1;
  }
  fseek(f, 0, SEEK_END);
  long size = ftell(f);
  fseek(f, 0, SEEK_SET);
  unsigned char *buf = malloc(size > 0 ? (size_t)size : 1);
  size_t got = buf ? fread(buf, 1, (size_t)size, f) : 0;
  fclose(f);
  static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!buf || got != (size_t)size || size < 8 || memcmp(buf, sig, 8) != 0) {
    fprintf(stderr, "png_read: %s is not a PNG file\n", path);
    free(buf);
    return -1;
  }
  unsigned char *idat = NULL, palette[256][3] = {{0}};
  size_t n_idat = 0;
  int depth = 0, type = -1, interlace = 0, ok = 1;
  for (size_t p = 8; ok && p + 12 <= (size_t)size;) {
    uint32_t len = png_be32(buf + p);
    const unsigned char *t = buf + p + 4, *d = buf + p + 8;
    if (p + 12 + len > (size_t)size) {
      ok = 0;
      break;
    }
    if (!memcmp(t, "IHDR", 4) && len >= 13) {
      img->width = png_be32(d);
      img->height = png_be32(d + 4);
      depth = d[8];
      type = d[9];
      interlace = d[12];
    } else if (!memcmp(t, "PLTE", 4)) {
      for (uint32_t i = 0; i < len / 3 && i < 256; ++i) memcpy(palette[i], d + 3 * i, 3);
    } else if (!memcmp(t, "IDAT", 4)) {
      unsigned char *m = realloc(idat, n_idat + len + 1);
      if (!m) {
        ok = 0;
        break;
      }
      idat = m;
      memcpy(idat + n_idat, d, len);
      n_idat += len;
    } else if (!memcmp(t, "IEND", 4)) {
      break;
    }
    p += 12 + len;
  }
  int bpp = type == 0 ? 1 : type == 2 ? 3 : type == 3 ? 1 : type == 4 ? 2 : type == 6 ? 4 : 0;
  if (!ok || depth != 8 || bpp == 0 || interlace || !img->width || !img->height || !idat) {
    fprintf(stderr, "png_read: %s: unsupported or damaged (depth %d, type %d, interlace %d)\n",
            path, depth, type, interlace);
    free(buf);
    free(idat);
    return -1;
  }
  size_t stride = (size_t)img->width * (size_t)bpp;
  uLongf raw_len = (uLongf)((stride + 1) * img->height);
  unsigned char *raw = malloc(raw_len);
  img->rgb = malloc((size_t)img->width * img->height * sizeof *img->rgb);
  if (!raw || !img->rgb || uncompress(raw, &raw_len, idat, (uLong)n_idat) != Z_OK ||
      raw_len != (stride + 1) * img->height || png_unfilter(raw, img->height, stride, bpp) != 0) {
    fprintf(stderr, "png_read: %s: cannot decode the image data\n", path);
    free(buf);
    free(idat);
    free(raw);
    free(img->rgb);
    img->rgb = NULL;
    return -1;
  }
  for (uint32_t y = 0; y < img->height; ++y)
    for (uint32_t x = 0; x < img->width; ++x) {
      const unsigned char *px = raw + y * (stride + 1) + 1 + (size_t)x * bpp;
      unsigned r, g, b, a = 255;
      if (type == 0 || type == 4) r = g = b = px[0];
      else if (type == 3) r = palette[px[0]][0], g = palette[px[0]][1], b = palette[px[0]][2];
      else r = px[0], g = px[1], b = px[2];
      if (type == 4) a = px[1];
      if (type == 6) a = px[3];
      /* over white */
      r = (r * a + 255 * (255 - a)) / 255;
      g = (g * a + 255 * (255 - a)) / 255;
      b = (b * a + 255 * (255 - a)) / 255;
      img->rgb[(size_t)y * img->width + x] = r << 16 | g << 8 | b;
    }
  free(buf);
  free(idat);
  free(raw);
  return 0;
}

/* Pixels of exactly colour rgb. */
static inline size_t png_count(const png_image *img, uint32_t rgb)
{
  size_t n = 0;
  for (size_t i = 0; i < (size_t)img->width * img->height; ++i) n += img->rgb[i] == rgb;
  return n;
}

/* Pixels that differ from the top-left pixel (the background). */
static inline size_t png_ink(const png_image *img)
{
  size_t n = (size_t)img->width * img->height;
  return n - png_count(img, img->rgb[0]);
}

/* Decodes a plot into *img and checks it has at least 1% of it drawn on (an empty frame with
 * its labels has 1.6%, a blank image 0), printing its size and ink. 0 when it did not
 * decode. */
static inline int png_read_drawn(const char *path, png_image *img)
{
  int ok = png_read(path, img) == 0;
  CHECK(ok);
  if (!ok) return 0;
  size_t ink = png_ink(img), all = (size_t)img->width * img->height;
  printf("  %s: %ux%u, %zu of %zu pixels drawn\n", path, img->width, img->height, ink, all);
  CHECK_LT(0.01 * all, (double)ink);
  return 1;
}

#endif
