/* SPDX-FileCopyrightText: 2026 The mcadsw authors */
/* SPDX-License-Identifier: Apache-2.0 */

/* Firmware in C99 for the MCADSW engine, written against the generated register map
 * driver/include/mcadsw/mcadsw_regs.h alone: identify the block, program a frame, start
 * it, read its outcome and acknowledge the interrupt. c_firmware_test.cpp runs frames
 * with it on the Verilated SoC; it is also the pattern for bare-metal or kernel code
 * (there the bus is a volatile pointer or ioread32 / iowrite32). */
#ifndef MCADSW_TEST_FIRMWARE_H
#define MCADSW_TEST_FIRMWARE_H

#include <stdint.h>

#include "mcadsw/mcadsw_regs.h"

#ifdef __cplusplus
extern "C" {
#endif

/* 32-bit register access at byte offsets from the block's base. */
struct mcadsw_bus {
  uint32_t (*read)(void *ctx, uint32_t offset);
  void (*write)(void *ctx, uint32_t offset, uint32_t value);
  void *ctx;
};

/* One frame (docs/memory_map.md): byte addresses, strides in bytes. */
struct mcadsw_frame {
  uint32_t base_ly, base_lu, base_lv, base_ry, base_ru, base_rv, base_out;
  uint32_t base_dl, base_dr, base_mask; /* LR mode */
  uint32_t stride, out_stride, tile_stride;
  uint32_t width, height, disparities;
  int subpixel, lr, right; /* CTRL.MODE */
  uint32_t lr_tolerance;
  uint32_t thresholds[MCADSW_WEIGHT_THRESHOLDS];
  int rect; /* rectification (RECT_CTRL.ENABLE) and its registers */
  uint32_t rect_step_log2, raw_width, raw_height, raw_stride;
  uint32_t raw_base[MCADSW_RAW_PLANES], mesh_base[2], valid_base[2];
  uint32_t mesh_nx, mesh_ny;
};

struct mcadsw_identity {
  uint32_t version_major, version_minor, dmax, par;
  int rect; /* the rectifier is built in */
};

/* What a frame left in the registers, read after its interrupt. */
struct mcadsw_outcome {
  int irq_done, irq_error;     /* IRQ_STATUS before the acknowledgement */
  int busy, done, error;       /* STATUS */
  uint32_t error_code;         /* enum mcadsw_error */
  const char *error_text;      /* mcadsw_error_text(error_code) */
  uint32_t cycles, words_read, words_written, stalls;
  uint32_t irq_after_ack;      /* IRQ_STATUS after DONE and ERROR were cleared: 0 */
};

/* 0 when ID and VERSION answer this register map (identity filled), -1 otherwise. */
int mcadsw_identify(const struct mcadsw_bus *bus, struct mcadsw_identity *id);
/* Every configuration register, the mode, and the interrupts on DONE and ERROR. */
void mcadsw_configure(const struct mcadsw_bus *bus, const struct mcadsw_frame *f);
/* Clears DONE and ERROR, then CTRL.START with the mode CTRL holds. */
void mcadsw_start(const struct mcadsw_bus *bus);
/* Reads the outcome of the frame, then acknowledges its interrupt. */
void mcadsw_finish(const struct mcadsw_bus *bus, struct mcadsw_outcome *out);

#ifdef __cplusplus
}
#endif

#endif /* MCADSW_TEST_FIRMWARE_H */
