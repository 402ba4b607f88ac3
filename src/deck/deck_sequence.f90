!> Sequence operations of the deck language on tuples and lists (doc/deck-language.md,
!> "Loops, indexing and modules"): indexing with negative indices, slicing with Python's
!> rules for omitted and out-of-range bounds, len, and the number of steps of range().
!> Each returns a message instead of a located status: the interpreter locates it.
module deck_sequence
    use kinds, only: dp, i8
    use strings, only: to_text
    use deck_value, only: value_t, value_list_t, VK_TUPLE, VK_LIST, VK_STR, nitems, &
        unpack_value, kind_label
    implicit none
    private
    public :: sequence_item, sequence_slice, sequence_length, range_steps

contains

    !> seq[index] for a tuple or list (index < 0 counts from the end, as in Python).
    !>  x : out, the item;  message : out, '' or what is wrong (index out of range, not a
    !>  sequence)
    subroutine sequence_item(seq, index, x, message)
        type(value_t), intent(in) :: seq
        integer(i8), intent(in) :: index
        type(value_t), intent(out) :: x
        character(len=:), allocatable, intent(out) :: message
        type(value_list_t) :: list
        integer(i8) :: n, k
        message = ''
        if (seq%kind /= VK_TUPLE .and. seq%kind /= VK_LIST) then
            message = kind_label(seq) // ' cannot be indexed (only a tuple or a list)'
            return
        end if
        n = nitems(seq)
        k = index
        if (k < 0) k = k + n
        if (k < 0 .or. k >= n) then
            message = 'index ' // to_text(index) // ' is out of range (' // &
                trim(kind_label(seq)) // ' of ' // to_text(n) // ' item(s): indices 0 to ' // &
                to_text(n - 1) // ', or -' // to_text(n) // ' to -1)'
            if (n == 0) message = 'index ' // to_text(index) // ' is out of range (' // &
                trim(kind_label(seq)) // ' is empty)'
            return
        end if
        list = unpack_value(seq)
        x = list%items(k + 1)
    end subroutine sequence_item

    !> seq[start:stop:step] for a tuple or list, Python's rules: omitted bounds are the ends
    !> (in the direction of step), negative bounds count from the end, out-of-range bounds
    !> are clipped. The result has the kind of seq.
    !>  given : in, which of start, stop, step are written;  bounds : in, their values
    !>  items : out, the selected items;  message : out, '' or what is wrong (step 0)
    subroutine sequence_slice(seq, given, bounds, items, message)
        type(value_t), intent(in) :: seq
        logical, intent(in) :: given(3)
        integer(i8), intent(in) :: bounds(3)
        type(value_t), allocatable, intent(out) :: items(:)
        character(len=:), allocatable, intent(out) :: message
        type(value_list_t) :: list
        integer(i8) :: n, start, stop, step, k, count
        message = ''
        allocate (items(0))
        if (seq%kind /= VK_TUPLE .and. seq%kind /= VK_LIST) then
            message = kind_label(seq) // ' cannot be sliced (only a tuple or a list)'
            return
        end if
        n = nitems(seq)
        step = 1
        if (given(3)) step = bounds(3)
        if (step == 0) then
            message = 'slice step cannot be zero'
            return
        end if
        step = max(-(n + 1), min(n + 1, step))   ! larger steps select the same items
        if (step > 0) then
            start = 0; stop = n
            if (given(1)) start = clip(bounds(1), 0_i8, n)
            if (given(2)) stop = clip(bounds(2), 0_i8, n)
            count = max(0_i8, (stop - start + step - 1) / step)
        else
            start = n - 1; stop = -1
            if (given(1)) start = clip(bounds(1), -1_i8, n - 1)
            if (given(2)) stop = clip(bounds(2), -1_i8, n - 1)
            count = max(0_i8, (start - stop - step - 1) / (-step))
        end if
        if (count == 0) return
        list = unpack_value(seq)
        deallocate (items)
        allocate (items(count))
        do k = 1, count
            items(k) = list%items(start + (k - 1) * step + 1)
        end do
    contains
        !> A bound as an index in [low, high]: negative counts from the end, then clipped.
        pure integer(i8) function clip(b, low, high)
            integer(i8), intent(in) :: b, low, high
            clip = b
            if (clip < 0) clip = clip + n
            clip = max(low, min(high, clip))
        end function clip
    end subroutine sequence_slice

    !> len(x): items of a tuple or list, characters of a string (UTF-8 code points).
    !>  n : out;  message : out, '' or what is wrong
    subroutine sequence_length(x, n, message)
        type(value_t), intent(in) :: x
        integer(i8), intent(out) :: n
        character(len=:), allocatable, intent(out) :: message
        integer :: i
        message = ''
        n = 0
        select case (x%kind)
        case (VK_TUPLE, VK_LIST)
            n = nitems(x)
        case (VK_STR)
            do i = 1, len(x%s)             ! continuation bytes 10xxxxxx are not characters
                if (iand(iachar(x%s(i:i)), 192) /= 128) n = n + 1
            end do
        case default
            message = 'len() needs a tuple, a list or a string, got ' // kind_label(x)
        end select
    end subroutine sequence_length

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
