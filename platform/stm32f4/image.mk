# image.mk - the STM32F4's build steps (BOARD_RULES): what a user flashes,
# written beside each ELF. The .bin starts at the vector table
# (0x08000000: st-flash write <backend>.bin 0x08000000); the .hex carries
# its own addresses (OpenOCD's program, STM32CubeProgrammer).
$(FW_DIR)/%.bin: $(FW_DIR)/%.elf
	$(show) OBJCOPY $@
	$(Q)$(FW_OBJCOPY) -O binary $< $@

$(FW_DIR)/%.hex: $(FW_DIR)/%.elf
	$(show) OBJCOPY $@
	$(Q)$(FW_OBJCOPY) -O ihex $< $@

