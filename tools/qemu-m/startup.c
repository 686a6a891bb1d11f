/* startup.c - reset for the examples under QEMU (mps2-an385, semihosting).
 *
 * The vector table holds the initial stack pointer and the reset handler;
 * reset zeroes .bss, paints the stack, opens semihosting's stdio (newlib's
 * rdimon), runs main and leaves QEMU with main's status.  Before leaving it
 * prints the RAM the program used: static (.data + .bss) and the stack's
 * high-water mark (the deepest painted word overwritten). */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

extern uint32_t __bss_start__[], __bss_end__[], __data_start__[], __stack_top[], __stack_limit[];
int main(int argc, char **argv);
void initialise_monitor_handles(void);
void reset_handler(void);

#define STACK_PAINT 0xA5A5A5A5u

/* ARM semihosting SYS_EXIT_EXTENDED (0x20): ADP_Stopped_ApplicationExit
 * with the status, which QEMU returns as its own exit status. */
static void semihosting_exit(int status)
{
    uint32_t block[2];
    register uint32_t r0 __asm__("r0") = 0x20;
    register uint32_t *r1 __asm__("r1") = block;
    block[0] = 0x20026; /* ADP_Stopped_ApplicationExit */
    block[1] = (uint32_t)status;
    __asm__ volatile("bkpt 0xab" : : "r"(r0), "r"(r1) : "memory");
    for (;;) {
    }
}

__attribute__((section(".vectors"), used)) static void (*const vectors[2])(void) = {
    (void (*)(void))__stack_top, reset_handler};

void reset_handler(void)
{
    uint32_t *p, sp;
    int status;
    for (p = __bss_start__; p < __bss_end__; p++) *p = 0;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    /* paint the stack below what reset itself is using */
    for (p = __stack_limit; (uint32_t)p < sp - 64; p++) *p = STACK_PAINT;
    initialise_monitor_handles();
    status = main(0, NULL);
    for (p = __stack_limit; p < __stack_top && *p == STACK_PAINT; p++) {
    }
    printf("cortex-m ram: static %lu bytes (.data + .bss), stack high-water %lu bytes\n",
           (unsigned long)((uint32_t)__bss_end__ - (uint32_t)__data_start__),
           (unsigned long)((uint32_t)__stack_top - (uint32_t)p));
    fflush(stdout);
    semihosting_exit(status);
}
