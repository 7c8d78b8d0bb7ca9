# Sourced by CI's lane scripts (kept out of .ci/lang, whose scripts are the lanes).
#
# steps_begin LANE    starts the lane's clock
# step TEXT           prints "-- LANE: TEXT (S s, C CPU s)" as a step begins: the seconds since
#                     steps_begin, and the CPU seconds (user + system) of every process the lane's
#                     shell has waited for so far, which is what two lanes side by side share.
#
# The CPU figure is the cutime and cstime fields of /proc/$$/stat ($$ is the lane's shell, in a
# subshell too), fields 16 and 17, counted after the parenthesised command name, which may hold
# spaces. Where there is no /proc (not Linux), the line gives the seconds alone.
steps_begin() {
    steps_lane=$1
    steps_started=$SECONDS
    steps_hz=$(getconf CLK_TCK 2>/dev/null || echo 100)
}

steps_cpu() {
    [ -r "/proc/$$/stat" ] || return 0
    local stat
    stat=$(<"/proc/$$/stat")
    # shellcheck disable=SC2086  # split on spaces into the fields after the name
    set -- ${stat##*) }
    # After the name: state is $1, so utime..cstime (fields 14..17) are $12..$15.
    local tenths=$(( ((${14} + ${15}) * 10 + steps_hz / 2) / steps_hz ))
    printf ', %d.%d CPU s' $((tenths / 10)) $((tenths % 10))
}

step() {
    echo "-- $steps_lane: $* ($((SECONDS - steps_started)) s$(steps_cpu))"
}
