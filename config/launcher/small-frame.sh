# tick1: a plain render of a small frame (at most 2^24 rays) is over before C2's compilations
# pay for themselves: the JIT stops at C1 for it. So does a diff, which parses two files and draws
# the handout's two small frames while the student's code runs in a JVM of its own, and a grade of
# one student's files at a small frame, which renders a few scenes beside that student's JVM. Any
# other subcommand, a cohort's grade (--submissions: many students, long enough for C2 to pay), or a
# bigger frame, keeps C2.
tick1_is_count() {
    case $1 in
        ''|0*|*[!0-9]*) return 1 ;;
    esac
    [ ${#1} -le 5 ]
}
tick1_small=yes
tick1_diff=no
tick1_width=640
tick1_height=480
tick1_samples=1
tick1_next=
for tick1_arg in "$@" ; do
    case $tick1_next in
        width) tick1_width=$tick1_arg ;;
        height) tick1_height=$tick1_arg ;;
        samples) tick1_samples=$tick1_arg ;;
    esac
    tick1_next=
    case $tick1_arg in
        --width|--height|--samples) tick1_next=${tick1_arg#--} ;;
        --width=*) tick1_width=${tick1_arg#*=} ;;
        --height=*) tick1_height=${tick1_arg#*=} ;;
        --samples=*) tick1_samples=${tick1_arg#*=} ;;
        diff) tick1_diff=yes ;;
        --submissions|--submissions=*) tick1_small=no ;;
        compare|diagnose|starter|vpl|bench|preview|help) tick1_small=no ;;
    esac
done
if [ $tick1_small = yes ] && { [ $tick1_diff = yes ] || { tick1_is_count "$tick1_width" &&
        tick1_is_count "$tick1_height" && tick1_is_count "$tick1_samples" &&
        [ $((tick1_width * tick1_height * tick1_samples)) -le 16777216 ] ; } ; } ; then
    DEFAULT_JVM_OPTS="$DEFAULT_JVM_OPTS \"-XX:TieredStopAtLevel=1\""
fi
