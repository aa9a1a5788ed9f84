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


# The variant's clock flags, as the firmware gets them: the host's clock
# test (tests/boards/stm32f4_clock_test.c) is built with the same
stm32-clock-flags:
	@echo '$(STM32_CLOCK_FLAGS)'

# the names of the variants (STM32=), from board.mk's table
stm32-variants:
	@echo '$(STM32_NAMES)'
