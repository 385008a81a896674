/* An HDF5 file built in memory (core driver, no backing store) and taken out as bytes.
 *
 * Why not let HDF5 write the file: in HDF5 1.10 an H5Fclose that fails to write (disk
 * full) leaves a dangling file identifier that crashes the program at exit (fixed only
 * in 1.14.1), and our own write() gives plain errno reasons. The price is memory: the
 * file twice over, briefly, at the end. */

#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/h5_util.h"
#include "util/error.h"
#include "util/huge_pages.h"

rs_status rs_h5_memfile_create(hid_t *file)
{
  static atomic_ulong counter;
  char detail[512], label[64];
  /* The name only labels the in-memory file, but must be unique among open files. */
  snprintf(label, sizeof label, "reelsim-in-memory-%lu", atomic_fetch_add(&counter, 1));
  *file = -1;
  hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
  /* The newest format this HDF5 writes (1.10's): every piece of metadata (superblock,
   * object headers, link and chunk indexes) then carries a checksum that HDF5 verifies
   * on reading; the 1.8 format still indexes chunks with unchecked v1 B-trees. */
  /* The core driver grows its buffer in steps of 64 KiB and zeroes each step as it takes
   * it: a larger step writes, and so has the kernel map, pages the file never uses (1 MiB
   * steps: a 555 kB file zeroed 1 MiB). Beyond glibc's mmap threshold a step is an
   * mremap, not a copy. */
  if (fapl < 0 || H5Pset_fapl_core(fapl, (size_t)1 << 16, 0) < 0 ||
      H5Pset_libver_bounds(fapl, H5F_LIBVER_LATEST, H5F_LIBVER_LATEST) < 0) {
    rs_h5_error_detail(detail, sizeof detail);
    if (fapl >= 0) H5Pclose(fapl);
    return RS_ERROR(RS_ERR_IO, "cannot set up an in-memory HDF5 file: %s", detail);
  }
  *file = H5Fcreate(label, H5F_ACC_EXCL, H5P_DEFAULT, fapl);
  if (*file < 0) rs_h5_error_detail(detail, sizeof detail);
  H5Pclose(fapl);
  if (*file < 0) return RS_ERROR(RS_ERR_IO, "cannot create an in-memory HDF5 file: %s", detail);
  return RS_OK;
}

static uint32_t rot32(uint32_t x, int k) { return (x << k) | (x >> (32 - k)); }

static uint32_t le32(const unsigned char *p, size_t n)
{
  uint32_t v = 0;
  for (size_t i = 0; i < n && i < 4; ++i) v |= (uint32_t)p[i] << (8 * i);
  return v;
}

/* The checksum of HDF5's metadata: Bob Jenkins' lookup3 hash ("hashlittle", initial
 * value 0) of the bytes, as the HDF5 file format specification names it. */
static uint32_t lookup3(const unsigned char *k, size_t n)
{
  uint32_t a, b, c;
  a = b = c = 0xdeadbeefu + (uint32_t)n;
  for (; n > 12; n -= 12, k += 12) {
    a += le32(k, 4);
    b += le32(k + 4, 4);
    c += le32(k + 8, 4);
    a -= c; a ^= rot32(c, 4); c += b;
    b -= a; b ^= rot32(a, 6); a += c;
    c -= b; c ^= rot32(b, 8); b += a;
    a -= c; a ^= rot32(c, 16); c += b;
    b -= a; b ^= rot32(a, 19); a += c;
    c -= b; c ^= rot32(b, 4); b += a;
  }
  if (n == 0) return c;
  a += le32(k, n);
  if (n > 4) b += le32(k + 4, n - 4);
  if (n > 8) c += le32(k + 8, n - 8);
  c ^= b; c -= rot32(b, 14);
  a ^= c; a -= rot32(c, 11);
  b ^= a; b -= rot32(a, 25);
  c ^= b; c -= rot32(b, 16);
  a ^= c; a -= rot32(c, 4);
  b ^= a; b -= rot32(a, 14);
  c ^= b; c -= rot32(b, 24);
  return c;
}

/* H5Fget_file_image of HDF5 1.10 clears the "open for writing" flag of a version 2 or 3
 * superblock in the copy but leaves the superblock's checksum as it was, so no HDF5
 * opens the image ("incorrect metadata checksum"). The superblock is signature, version,
 * the two sizes, the flags, four addresses, then the checksum of all that: compute it
 * again. Nothing is changed unless the old checksum is that of the flags set, so an
 * HDF5 that gets it right is left alone. */
static void fix_superblock_checksum(unsigned char *img, size_t size)
{
  static const unsigned char sig[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  if (size < 12 || memcmp(img, sig, 8) != 0 || (img[8] != 2 && img[8] != 3)) return;
  size_t offsets = img[9], body = 12 + 4 * offsets;
  if ((offsets != 4 && offsets != 8) || size < body + 4) return;
  uint32_t stored = le32(img + body, 4), now = lookup3(img, body);
  if (stored == now || img[11] != 0) return;
  for (unsigned flags = 1; flags < 8; ++flags) {
    img[11] = (unsigned char)flags;
    int was = lookup3(img, body) == stored;
    img[11] = 0;
    if (!was) continue;
    for (int i = 0; i < 4; ++i) img[body + (size_t)i] = (unsigned char)(now >> (8 * i));
    return;
  }
}

rs_status rs_h5_memfile_image(hid_t file, void **image, size_t *size)
{
  char detail[512];
  ssize_t n = -1;
  *image = NULL;
  *size = 0;
  /* H5Fget_file_image of 1.10 does not flush first: without this the image lacks the
   * metadata still in the cache (and chunks in the chunk cache) and is no valid file. */
  if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0 || (n = H5Fget_file_image(file, NULL, 0)) < 0) {
    rs_h5_error_detail(detail, sizeof detail);
    return RS_ERROR(RS_ERR_IO, "cannot finish the in-memory HDF5 file: %s", detail);
  }
  if (!(*image = malloc(n > 0 ? (size_t)n : 1)))
    return RS_ERROR(RS_ERR_MEMORY, "out of memory for a %zd-byte HDF5 file", n);
  (void)rs_huge_pages_advise(*image, (size_t)n); /* a long roll's file: touched whole, next */
  if (H5Fget_file_image(file, *image, (size_t)n) != n) {
    rs_h5_error_detail(detail, sizeof detail);
    free(*image);
    *image = NULL;
    return RS_ERROR(RS_ERR_IO, "cannot copy the in-memory HDF5 file: %s", detail);
  }
  *size = (size_t)n;
  fix_superblock_checksum(*image, *size);
  return RS_OK;
}
