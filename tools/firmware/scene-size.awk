# scene-size.awk - an NFF scene's `resolution` as WxH (firmware.mk's SIZE
# unless given), read as the reader (src/reader/) reads it: blank-separated
# tokens, '#' to the end of the line a comment, the two whole numbers after
# the viewpoint's `resolution` keyword (32.0 and 3.2e1 are 32 too). Prints
# nothing when there is none or they are not whole numbers: the reader
# then says what is wrong. tests/boards/board-tests.sh checks it against rt for
# every scene of scenes/.
function whole(t) {
    return t ~ /^[+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][+-]?[0-9]+)?$/ && t + 0 >= 1 && t + 0 == int(t + 0)
}
{
    gsub(/[\r\t\f\v]/, " ")
    sub(/#.*/, "")
    for (i = 1; i <= NF; i++) {
        if (want == 0) {
            if ($i == "resolution")
                want = 2
        } else if (want == 2) {
            w = $i
            want = 1
        } else {
            if (whole(w) && whole($i))
                printf "%dx%d\n", w + 0, $i + 0
            exit
        }
    }
}
