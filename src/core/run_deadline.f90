!> A wall-clock limit on one run: the `P time_limit SECONDS` line of a Code_Aster export
!> file (doc/aster-tests.md). The run context holds one; the deck layer polls it between
!> commands and loop iterations, the analysis layer between Newton iterations (it receives
!> a copy in its options), so a run stops with a clear message instead of running past
!> its limit. Polling costs one system_clock call. An unset deadline never expires.
module run_deadline
    use kinds, only: dp, i8
    use status, only: status_t, set_error, STATUS_IO_ERROR
    implicit none
    private

    !> A deadline. `origin` is the clock count at the start of the run, `limit` the allowed
    !> wall-clock seconds from there, `what` names where the limit was given (for messages:
    !> 'ssnl130a.export:1 (P time_limit 60)').
    type, public :: deadline_t
        logical :: active = .false.
        integer(i8) :: origin = 0, rate = 1
        real(dp) :: limit = 0.0_dp
        character(len=:), allocatable :: what
    contains
        procedure :: start => deadline_start
        procedure :: elapsed => deadline_elapsed
        procedure :: expired => deadline_expired
        procedure :: check => deadline_check
    end type deadline_t

contains

    !> Starts counting `seconds` of wall-clock time from now.
    !>  seconds : in, > 0;  what : in, where the limit comes from (for the message)
    subroutine deadline_start(self, seconds, what)
        class(deadline_t), intent(inout) :: self
        real(dp), intent(in) :: seconds
        character(len=*), intent(in) :: what
        call system_clock(self%origin, self%rate)
        self%rate = max(self%rate, 1_i8)
        self%limit = seconds
        self%what = what
        self%active = .true.
    end subroutine deadline_start

    !> Wall-clock seconds since start (0 for an unset deadline).
    real(dp) function deadline_elapsed(self)
        class(deadline_t), intent(in) :: self
        integer(i8) :: now
        deadline_elapsed = 0.0_dp
        if (.not. self%active) return
        call system_clock(now)
        deadline_elapsed = real(now - self%origin, dp) / real(self%rate, dp)
    end function deadline_elapsed

    !> True once the limit is passed.
    logical function deadline_expired(self)
        class(deadline_t), intent(in) :: self
        deadline_expired = .false.
        if (.not. self%active) return
        deadline_expired = self%elapsed() > self%limit
    end function deadline_expired

    !> Sets st to an error when the limit is passed (st is left untouched otherwise).
    !>  during : in, what was running ('STAT_NON_LINE, INST 1.5, Newton iteration 3')
    !>  st : inout, STATUS_IO_ERROR "time limit of N s exceeded (...)"
    subroutine deadline_check(self, during, st)
        class(deadline_t), intent(in) :: self
        character(len=*), intent(in) :: during
        type(status_t), intent(inout) :: st
        real(dp) :: t
        if (.not. self%active) return
        t = self%elapsed()
        if (t <= self%limit) return
        call set_error(st, STATUS_IO_ERROR, 'time limit of ' // seconds_text(self%limit) // &
            ' s exceeded after ' // seconds_text(t) // ' s, during ' // during // &
            ' (the limit is ' // self%what // '; raise it to let the run finish)')
    end subroutine deadline_check

    !> Seconds for a message: '60', '0.500', '61.2'.
    function seconds_text(x) result(text)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: text
        character(len=32) :: buf
        if (abs(x - anint(x)) < 1.0e-9_dp .and. abs(x) < 1.0e9_dp) then
            write (buf, '(i0)') nint(x, i8)
        else if (x < 10.0_dp) then
            write (buf, '(f0.3)') x
        else
            write (buf, '(f0.1)') x
        end if
        text = trim(buf)
        if (text(1:1) == '.') text = '0' // text
    end function seconds_text

end module run_deadline
