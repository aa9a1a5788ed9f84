# image.mk - the Pico's own build steps (BOARD_RULES in board.mk),
# included by app/firmware/firmware.mk after its rules:
#  - boot2: boot2.S assembled for SRAM 0x20041f00 (where the boot ROM
#    runs it), padded to 252 bytes and followed by its CRC
#    (tools/emu/pico/uf2.mjs), as the .boot2 section that link.ld puts
#    first in flash;
#  - <backend>.uf2 beside each ELF: its flash image as UF2 blocks for the
#    RPI-RP2 drive (family RP2040), checked as it is written, and, with
#    the panel, that it draws the frame make built it for on that panel;
#  - make uf2, the same as make image: that file copied to out/, as
#    make run does, and checked.
PICO_BOOT2 := $(FW_ROOT)/pico/boot2

$(PICO_BOOT2)/boot2.elf: platform/pico/boot2.S platform/pico/image.mk
	@mkdir -p $(@D)
	$(show) LD $@
	$(Q)$(FW_CC) $(BOARD_CPU) -nostdlib -nostartfiles -Wl,-Ttext=0x20041f00 -o $@ $<

$(PICO_BOOT2)/boot2.bin: $(PICO_BOOT2)/boot2.elf
	$(show) OBJCOPY $@
	$(Q)$(FW_OBJCOPY) -O binary $< $@

$(PICO_BOOT2)/boot2_crc.S: $(PICO_BOOT2)/boot2.bin tools/emu/pico/uf2.mjs
	$(show) BOOT2 $@
	$(Q)node tools/emu/pico/uf2.mjs boot2 $< $@

$(PICO_BOOT2)/boot2_crc.o: $(PICO_BOOT2)/boot2_crc.S
	$(show) AS $@
	$(Q)$(FW_CC) $(BOARD_CPU) -c $< -o $@

$(FW_DIR)/%.bin: $(FW_DIR)/%.elf
	$(show) OBJCOPY $@
	$(Q)$(FW_OBJCOPY) -O binary $< $@

$(FW_DIR)/%.uf2: $(FW_DIR)/%.bin tools/emu/pico/uf2.mjs
	$(show) UF2 $@
	$(Q)node tools/emu/pico/uf2.mjs pack $< $@
	@node tools/emu/pico/uf2.mjs check $@ $(if $(filter st7789,$(PICO_DISPLAY)),--expect "frame $(SIZE) centred on the $(PANEL) ST7789 panel") >/dev/null

# make uf2: make image by the name Pico users look for
uf2: image
