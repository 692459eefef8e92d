/* SPDX-FileCopyrightText: 2026 The mcadsw authors */
/* SPDX-License-Identifier: Apache-2.0 */

/* The C firmware of firmware.h: registers by the names of mcadsw/mcadsw_regs.h only. */
#include "firmware.h"

static uint32_t rd(const struct mcadsw_bus *bus, uint32_t offset) { return bus->read(bus->ctx, offset); }
static void wr(const struct mcadsw_bus *bus, uint32_t offset, uint32_t value) {
  bus->write(bus->ctx, offset, value);
}

int mcadsw_identify(const struct mcadsw_bus *bus, struct mcadsw_identity *id) {
  const uint32_t version = rd(bus, MCADSW_REG_VERSION);
  const uint32_t hw = rd(bus, MCADSW_REG_HWCONFIG);
  id->version_major = MCADSW_GET(version, VERSION_MAJOR);
  id->version_minor = MCADSW_GET(version, VERSION_MINOR);
  id->dmax = MCADSW_GET(hw, HWCONFIG_DMAX);
  id->par = MCADSW_GET(hw, HWCONFIG_PAR);
  id->rect = MCADSW_GET(hw, HWCONFIG_NORECT) == 0;
  if (rd(bus, MCADSW_REG_ID) != MCADSW_ID_MAGIC) return -1;
  if (id->version_major != MCADSW_MAP_VERSION_MAJOR || id->version_minor < MCADSW_MAP_VERSION_MINOR) return -1;
  return 0;
}

void mcadsw_configure(const struct mcadsw_bus *bus, const struct mcadsw_frame *f) {
  int i;
  uint32_t mode;
  wr(bus, MCADSW_REG_BASE_LY, f->base_ly);
  wr(bus, MCADSW_REG_BASE_LU, f->base_lu);
  wr(bus, MCADSW_REG_BASE_LV, f->base_lv);
  wr(bus, MCADSW_REG_BASE_RY, f->base_ry);
  wr(bus, MCADSW_REG_BASE_RU, f->base_ru);
  wr(bus, MCADSW_REG_BASE_RV, f->base_rv);
  wr(bus, MCADSW_REG_BASE_OUT, f->base_out);
  wr(bus, MCADSW_REG_BASE_DL, f->base_dl);
  wr(bus, MCADSW_REG_BASE_DR, f->base_dr);
  wr(bus, MCADSW_REG_BASE_MASK, f->base_mask);
  wr(bus, MCADSW_REG_STRIDE, f->stride);
  wr(bus, MCADSW_REG_OUT_STRIDE, f->out_stride);
  wr(bus, MCADSW_REG_TILE_STRIDE, f->tile_stride);
  wr(bus, MCADSW_REG_SIZE, MCADSW_PUT(f->width, SIZE_WIDTH) | MCADSW_PUT(f->height, SIZE_HEIGHT));
  wr(bus, MCADSW_REG_DISP, MCADSW_PUT(f->disparities, DISP_D));
  wr(bus, MCADSW_REG_LR_T, MCADSW_PUT(f->lr_tolerance, LR_T_T));
  for (i = 0; i < MCADSW_WEIGHT_THRESHOLDS; ++i)
    wr(bus, MCADSW_REG_THR0 + 4u * (uint32_t)i, mcadsw_put(f->thresholds[i], 0, MCADSW_THR_BITS));
  wr(bus, MCADSW_REG_RECT_CTRL,
     MCADSW_PUT((uint32_t)(f->rect != 0), RECT_CTRL_ENABLE) | MCADSW_PUT(f->rect_step_log2, RECT_CTRL_STEP_LOG2));
  wr(bus, MCADSW_REG_RAW_SIZE, MCADSW_PUT(f->raw_width, RAW_SIZE_WIDTH) | MCADSW_PUT(f->raw_height, RAW_SIZE_HEIGHT));
  wr(bus, MCADSW_REG_RAW_STRIDE, f->raw_stride);
  for (i = 0; i < MCADSW_RAW_PLANES; ++i) wr(bus, MCADSW_REG_RAW_LY + 4u * (uint32_t)i, f->raw_base[i]);
  wr(bus, MCADSW_REG_MESH_L, f->mesh_base[0]);
  wr(bus, MCADSW_REG_MESH_R, f->mesh_base[1]);
  wr(bus, MCADSW_REG_MESH_NODES, MCADSW_PUT(f->mesh_nx, MESH_NODES_NX) | MCADSW_PUT(f->mesh_ny, MESH_NODES_NY));
  wr(bus, MCADSW_REG_VALID_L, f->valid_base[0]);
  wr(bus, MCADSW_REG_VALID_R, f->valid_base[1]);
  mode = (uint32_t)(f->subpixel != 0) << MCADSW_MODE_SUBPIXEL_BIT | (uint32_t)(f->lr != 0) << MCADSW_MODE_LR_BIT |
         (uint32_t)(f->right != 0) << MCADSW_MODE_RIGHT_BIT;
  wr(bus, MCADSW_REG_CTRL, MCADSW_PUT(mode, CTRL_MODE));
  wr(bus, MCADSW_REG_IRQ_ENABLE, MCADSW_IRQ_ENABLE_DONE_MASK | MCADSW_IRQ_ENABLE_ERROR_MASK);
}

void mcadsw_start(const struct mcadsw_bus *bus) {
  wr(bus, MCADSW_REG_STATUS, MCADSW_STATUS_DONE_MASK | MCADSW_STATUS_ERROR_MASK);
  wr(bus, MCADSW_REG_CTRL, rd(bus, MCADSW_REG_CTRL) | MCADSW_CTRL_START_MASK);
}

void mcadsw_finish(const struct mcadsw_bus *bus, struct mcadsw_outcome *out) {
  const uint32_t irq = rd(bus, MCADSW_REG_IRQ_STATUS);
  const uint32_t status = rd(bus, MCADSW_REG_STATUS);
  out->irq_done = MCADSW_GET(irq, IRQ_STATUS_DONE) != 0;
  out->irq_error = MCADSW_GET(irq, IRQ_STATUS_ERROR) != 0;
  out->busy = MCADSW_GET(status, STATUS_BUSY) != 0;
  out->done = MCADSW_GET(status, STATUS_DONE) != 0;
  out->error = MCADSW_GET(status, STATUS_ERROR) != 0;
  out->error_code = MCADSW_GET(status, STATUS_ERROR_CODE);
  out->error_text = mcadsw_error_text(out->error_code);
  out->cycles = rd(bus, MCADSW_REG_CYCLES);
  out->words_read = rd(bus, MCADSW_REG_WORDS_READ);
  out->words_written = rd(bus, MCADSW_REG_WORDS_WRITTEN);
  out->stalls = rd(bus, MCADSW_REG_STALLS);
  wr(bus, MCADSW_REG_STATUS, MCADSW_STATUS_DONE_MASK | MCADSW_STATUS_ERROR_MASK);
  out->irq_after_ack = rd(bus, MCADSW_REG_IRQ_STATUS);
}
