# Sourced by CI's lane scripts (kept out of .ci/lang, whose scripts are the lanes), and by .ci/run
# for its own CPU figures (steps_ticks).
#
# steps_begin LANE    starts the lane's clock
# step TEXT           prints "-- LANE: TEXT (S s, C CPU s)" as a step begins: the seconds since
#                     steps_begin, and the CPU seconds (user + system) of every process the lane's
#                     shell has waited for so far, which is what two lanes side by side share.
#
# The CPU figure is the cutime and cstime fields of /proc/$$/stat ($$ is the lane's shell, in a
# subshell too), fields 16 and 17, counted after the parenthesised command name, which may hold
# spaces; in a subshell, with the subshell's own and its children's. Where there is no /proc (not
# Linux), the line gives the seconds alone.
steps_begin() {
    steps_lane=$1
    steps_started=$SECONDS
    steps_hz=$(getconf CLK_TCK 2>/dev/null || echo 100)
}

# steps_cpu SHELL: SHELL is the process of the shell that runs the step ($BASHPID, read before the
# $( ) that calls this, which is a process of its own).
steps_cpu() {
    [ -r "/proc/$$/stat" ] || return 0
    local ticks me=$1
    ticks=$(steps_ticks "$$" waited)
    # In a subshell ( ... ), what it has waited for reaches the lane's shell only when it ends: its
    # own children's time and its own are added until then.
    if [ "$me" != "$$" ]; then
        ticks=$(( ticks + $(steps_ticks "$me" all) ))
    fi
    local tenths=$(( (ticks * 10 + steps_hz / 2) / steps_hz ))
    printf ', %d.%d CPU s' $((tenths / 10)) $((tenths % 10))
}

# steps_ticks PID waited|all: clock ticks of the children PID has waited for (cutime + cstime), or
# those and PID's own (utime + stime) too.
steps_ticks() {
    local stat
    stat=$(<"/proc/$1/stat")
    # shellcheck disable=SC2086  # split on spaces into the fields after the name
    set -- ${stat##*) } "$2"
    # After the name: state is $1, so utime..cstime (fields 14..17) are $12..$15; the mode is last.
    if [ "${!#}" = all ]; then
        echo $(( ${12} + ${13} + ${14} + ${15} ))
    else
        echo $(( ${14} + ${15} ))
    fi
}

step() {
    local shell=$BASHPID
    echo "-- $steps_lane: $* ($((SECONDS - steps_started)) s$(steps_cpu "$shell"))"
}
