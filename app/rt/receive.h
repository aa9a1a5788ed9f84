/* receive.h - `rt receive`: the board's framed UART stream to an image. */
#ifndef RECEIVE_H
#define RECEIVE_H

/* argv[0] is "receive". */
int cmd_receive(int argc, char **argv);

#endif
