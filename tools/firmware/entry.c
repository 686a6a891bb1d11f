/* entry.c - the least a Cortex-M image needs to run main: a vector table
 * (initial stack pointer, reset handler) and a reset that zeroes .bss and
 * calls main.  The firmware apps of make firmware-check link with it
 * (-nostartfiles) so that their size is theirs and rastrum's, not a C
 * runtime's. */
#include <stdint.h>

extern uint32_t __bss_start__[], __bss_end__[], __stack_top[];
int main(void);
void reset_handler(void);

__attribute__((section(".vectors"), used)) static void (*const vectors[2])(void) = {
    (void (*)(void))__stack_top, reset_handler};

void reset_handler(void)
{
    uint32_t *p;
    for (p = __bss_start__; p < __bss_end__; p++) *p = 0;
    (void)main();
    for (;;) {
    }
}
