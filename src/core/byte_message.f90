!> A message of bytes between two processes (child_process): integers, reals, texts and
!> arrays put one after another and taken back in the same order. Used by the MED server
!> (src/mesh/med_server.f90), which runs the MED library in a child process.
!>
!> Taking more than the message holds, or a count that does not fit what is left, does not
!> fail loudly: the message is marked `bad`, zeros and empty values come back, and the
!> reader checks `bad` once it has taken what it expected.
module byte_message
    use, intrinsic :: iso_c_binding, only: c_char, c_int, c_double
    use kinds, only: i4, i8, dp
    implicit none
    private

    !> Bytes of the integers and reals carried (c_int, c_double).
    integer, parameter :: INT_BYTES = 4, REAL_BYTES = 8

    type, public :: message_t
        character(kind=c_char), allocatable :: bytes(:)
        integer(i8) :: length = 0   !< bytes put so far
        integer(i8) :: cursor = 0   !< bytes taken so far
        logical :: bad = .false.    !< something was taken beyond the end
    contains
        procedure :: clear => message_clear
        procedure :: put_int => message_put_int
        procedure :: put_ints => message_put_ints
        procedure :: put_real => message_put_real
        procedure :: put_reals => message_put_reals
        procedure :: put_text => message_put_text
        procedure :: put_chars => message_put_chars
        procedure :: get_int => message_get_int
        procedure :: get_ints => message_get_ints
        procedure :: get_real => message_get_real
        procedure :: get_reals => message_get_reals
        procedure :: get_text => message_get_text
        procedure :: get_chars => message_get_chars
    end type message_t

contains

    !> Empties the message (its storage is kept).
    subroutine message_clear(self)
        class(message_t), intent(inout) :: self
        self%length = 0
        self%cursor = 0
        self%bad = .false.
    end subroutine message_clear

    ! Room for n more bytes.
    subroutine reserve(self, n)
        class(message_t), intent(inout) :: self
        integer(i8), intent(in) :: n
        character(kind=c_char), allocatable :: grown(:)
        integer(i8) :: capacity
        if (.not. allocated(self%bytes)) allocate (self%bytes(max(n, 4096_i8)))
        if (self%length + n <= size(self%bytes, kind=i8)) return
        capacity = max(2 * size(self%bytes, kind=i8), self%length + n)
        allocate (grown(capacity))
        grown(1:self%length) = self%bytes(1:self%length)
        call move_alloc(grown, self%bytes)
    end subroutine reserve

    ! Appends raw bytes.
    subroutine append(self, raw)
        class(message_t), intent(inout) :: self
        character(kind=c_char), intent(in) :: raw(:)
        integer(i8) :: n
        n = size(raw, kind=i8)
        call reserve(self, n)
        self%bytes(self%length + 1:self%length + n) = raw
        self%length = self%length + n
    end subroutine append

    ! The next n bytes start at `first` (and the cursor moves past them); ok = .false. (the
    ! message marked bad) when fewer remain.
    subroutine take(self, n, first, ok)
        class(message_t), intent(inout) :: self
        integer(i8), intent(in) :: n
        integer(i8), intent(out) :: first
        logical, intent(out) :: ok
        first = self%cursor + 1
        ok = .not. self%bad .and. n >= 0 .and. n <= self%length - self%cursor
        if (.not. ok) then
            self%bad = .true.
            return
        end if
        self%cursor = self%cursor + n
    end subroutine take

    subroutine message_put_int(self, value)
        class(message_t), intent(inout) :: self
        integer, intent(in) :: value
        character(kind=c_char) :: mold(1)
        call append(self, transfer(int(value, c_int), mold, INT_BYTES))
    end subroutine message_put_int

    !> A count, then the values.
    subroutine message_put_ints(self, values)
        class(message_t), intent(inout) :: self
        integer(i4), intent(in) :: values(:)
        character(kind=c_char) :: mold(1)
        call self%put_int(size(values))
        if (size(values) > 0) call append(self, transfer(values, mold, INT_BYTES * size(values)))
    end subroutine message_put_ints

    subroutine message_put_real(self, value)
        class(message_t), intent(inout) :: self
        real(dp), intent(in) :: value
        character(kind=c_char) :: mold(1)
        call append(self, transfer(real(value, c_double), mold, REAL_BYTES))
    end subroutine message_put_real

    !> A count, then the values.
    subroutine message_put_reals(self, values)
        class(message_t), intent(inout) :: self
        real(dp), intent(in) :: values(:)
        character(kind=c_char) :: mold(1)
        call self%put_int(size(values))
        if (size(values) > 0) &
            call append(self, transfer(values, mold, REAL_BYTES * size(values)))
    end subroutine message_put_reals

    !> A length, then the characters.
    subroutine message_put_text(self, text)
        class(message_t), intent(inout) :: self
        character(len=*), intent(in) :: text
        character(kind=c_char) :: mold(1)
        call self%put_int(len(text))
        if (len(text) > 0) call append(self, transfer(text, mold, len(text)))
    end subroutine message_put_text

    !> A count, then the characters of a C buffer.
    subroutine message_put_chars(self, chars)
        class(message_t), intent(inout) :: self
        character(kind=c_char), intent(in) :: chars(:)
        call self%put_int(size(chars))
        if (size(chars) > 0) call append(self, chars)
    end subroutine message_put_chars

    integer(i4) function message_get_int(self) result(value)
        class(message_t), intent(inout) :: self
        integer(i8) :: p
        integer(c_int) :: mold
        logical :: ok
        value = 0
        call take(self, int(INT_BYTES, i8), p, ok)
        if (.not. ok) return
        value = int(transfer(self%bytes(p:p + INT_BYTES - 1), mold), i4)
    end function message_get_int

    !> Values put by put_ints (empty when the message is bad).
    subroutine message_get_ints(self, values)
        class(message_t), intent(inout) :: self
        integer(i4), allocatable, intent(out) :: values(:)
        integer(i8) :: p
        integer :: n
        logical :: ok
        n = self%get_int()
        ok = .false.
        if (n > 0) call take(self, int(INT_BYTES, i8) * n, p, ok)
        if (.not. ok) then
            allocate (values(0))
            return
        end if
        allocate (values(n))
        values = transfer(self%bytes(p:p + int(INT_BYTES, i8) * n - 1), values, n)
    end subroutine message_get_ints

    real(dp) function message_get_real(self) result(value)
        class(message_t), intent(inout) :: self
        integer(i8) :: p
        logical :: ok
        value = 0.0_dp
        call take(self, int(REAL_BYTES, i8), p, ok)
        if (.not. ok) return
        value = transfer(self%bytes(p:p + REAL_BYTES - 1), value)
    end function message_get_real

    !> Values put by put_reals (empty when the message is bad).
    subroutine message_get_reals(self, values)
        class(message_t), intent(inout) :: self
        real(dp), allocatable, intent(out) :: values(:)
        integer(i8) :: p
        integer :: n
        logical :: ok
        n = self%get_int()
        ok = .false.
        if (n > 0) call take(self, int(REAL_BYTES, i8) * n, p, ok)
        if (.not. ok) then
            allocate (values(0))
            return
        end if
        allocate (values(n))
        values = transfer(self%bytes(p:p + int(REAL_BYTES, i8) * n - 1), values, n)
    end subroutine message_get_reals

    !> A text put by put_text ('' when the message is bad).
    function message_get_text(self) result(text)
        class(message_t), intent(inout) :: self
        character(len=:), allocatable :: text
        integer(i8) :: p
        integer :: n, k
        logical :: ok
        n = self%get_int()
        text = ''
        ok = .false.
        if (n > 0) call take(self, int(n, i8), p, ok)
        if (.not. ok) return
        text = repeat(' ', n)
        do k = 1, n
            text(k:k) = self%bytes(p + k - 1)
        end do
    end function message_get_text

    !> A C buffer put by put_chars (empty when the message is bad).
    subroutine message_get_chars(self, chars)
        class(message_t), intent(inout) :: self
        character(kind=c_char), allocatable, intent(out) :: chars(:)
        integer(i8) :: p
        integer :: n
        logical :: ok
        n = self%get_int()
        ok = .false.
        if (n > 0) call take(self, int(n, i8), p, ok)
        if (.not. ok) then
            allocate (chars(0))
            return
        end if
        chars = self%bytes(p:p + n - 1)
    end subroutine message_get_chars

end module byte_message
