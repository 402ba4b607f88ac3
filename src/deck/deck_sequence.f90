!> Index arithmetic of the deck language's sequences (doc/deck-language.md, "Sequences"),
!> Python's rules: an index counts from the end when negative; a slice's omitted bounds are
!> the ends in the direction of its step, its negative bounds count from the end and its
!> out-of-range bounds are clipped; range() counts its steps without building them. Each
!> returns a message instead of a located status: the interpreter locates it.
module deck_sequence
    use kinds, only: dp, i8
    use strings, only: to_text
    implicit none
    private
    public :: item_position, slice_positions, range_steps

contains

    !> The 1-based position of seq[index] in a sequence of n items.
    !>  what : in, the sequence in words for the message ('a list');  message : out, '' or
    !>  why the index is out of range
    subroutine item_position(n, index, what, k, message)
        integer, intent(in) :: n
        integer(i8), intent(in) :: index
        character(len=*), intent(in) :: what
        integer, intent(out) :: k
        character(len=:), allocatable, intent(out) :: message
        integer(i8) :: j
        message = ''
        k = 0
        j = index
        if (j < 0) j = j + n
        if (j < 0 .or. j >= n) then
            if (n == 0) then
                message = 'index ' // to_text(index) // ' is out of range (' // what // &
                    ' is empty)'
            else
                message = 'index ' // to_text(index) // ' is out of range (' // what // &
                    ' of ' // to_text(n) // ' item(s): indices 0 to ' // to_text(n - 1) // &
                    ', or -' // to_text(n) // ' to -1)'
            end if
            return
        end if
        k = int(j) + 1
    end subroutine item_position

    !> The 1-based positions seq[start:stop:step] selects in a sequence of n items: first,
    !> step and count.
    !>  given : in, which of start, stop, step are written;  bounds : in, their values
    !>  message : out, '' or what is wrong (step 0)
    subroutine slice_positions(n, given, bounds, first, step, count, message)
        integer, intent(in) :: n
        logical, intent(in) :: given(3)
        integer(i8), intent(in) :: bounds(3)
        integer, intent(out) :: first, step, count
        character(len=:), allocatable, intent(out) :: message
        integer(i8) :: start, stop, s, c
        message = ''
        first = 1; step = 1; count = 0
        s = 1
        if (given(3)) s = bounds(3)
        if (s == 0) then
            message = 'slice step cannot be zero'
            return
        end if
        s = max(-int(n, i8) - 1, min(int(n, i8) + 1, s))   ! larger steps select the same
        if (s > 0) then
            start = 0; stop = n
            if (given(1)) start = clip(bounds(1), 0_i8, int(n, i8))
            if (given(2)) stop = clip(bounds(2), 0_i8, int(n, i8))
            c = max(0_i8, (stop - start + s - 1) / s)
        else
            start = n - 1; stop = -1
            if (given(1)) start = clip(bounds(1), -1_i8, int(n, i8) - 1)
            if (given(2)) stop = clip(bounds(2), -1_i8, int(n, i8) - 1)
            c = max(0_i8, (start - stop - s - 1) / (-s))
        end if
        first = int(start) + 1; step = int(s); count = int(c)
    contains
        !> A bound as an index in [low, high]: negative counts from the end, then clipped.
        pure integer(i8) function clip(b, low, high)
            integer(i8), intent(in) :: b, low, high
            clip = b
            if (clip < 0) clip = clip + n
            clip = max(low, min(high, clip))
        end function clip
    end subroutine slice_positions

    !> Number of values of range(start, stop, step) (Python semantics; 0 when empty).
    !>  message : out, '' or 'range() step cannot be zero'
    subroutine range_steps(start, stop, step, count, message)
        integer(i8), intent(in) :: start, stop, step
        integer(i8), intent(out) :: count
        character(len=:), allocatable, intent(out) :: message
        real(dp) :: span
        message = ''
        count = 0
        if (step == 0) then
            message = 'range() step cannot be zero'
            return
        end if
        ! In reals first: stop - start can leave the 64-bit range.
        span = (real(stop, dp) - real(start, dp)) / real(step, dp)
        if (span <= 0.0_dp) return
        if (span > 9.0e18_dp) then
            count = huge(count)
            return
        end if
        if (step > 0) then
            count = (stop - start + step - 1) / step
        else
            count = (start - stop - step - 1) / (-step)
        end if
    end subroutine range_steps

end module deck_sequence
