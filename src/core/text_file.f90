!> Text files read whole: the bytes at once with stream access (no record I/O, lines of any
!> length), then split into lines (LF or CRLF ends; a last line without an end counts).
!> Used where parasol reads back a text file (LIRE_TABLE, a unit file written earlier in
!> the run that a command adds to).
module text_file
    use kinds, only: i4, i8
    use strings, only: string_t
    use status, only: status_t, set_error, STATUS_IO_ERROR
    use system_error, only: readable_errno, errno_text
    implicit none
    private

    !> Largest file read (bytes): the text is one buffer indexed by default integers.
    integer(i8), parameter, public :: MAX_TEXT_FILE_BYTES = int(huge(1_i4), i8)

    public :: read_text_file, split_text_lines

contains

    !> The bytes of `path`.
    !>  what : in, how messages name the file (e.g. 'table file')
    !>  st   : STATUS_IO_ERROR naming the path and the system's reason, or the size limit
    subroutine read_text_file(path, what, text, st)
        character(len=*), intent(in) :: path, what
        character(len=:), allocatable, intent(out) :: text
        type(status_t), intent(inout) :: st
        integer :: unit, ios, code
        integer(i8) :: nbytes
        character(len=256) :: msg
        text = ''
        code = readable_errno(path)
        if (code /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot open ' // what // ' ' // path // &
                ': ' // errno_text(code))
            return
        end if
        open (newunit=unit, file=path, access='stream', form='unformatted', status='old', &
              action='read', iostat=ios)
        if (ios /= 0) then
            call set_error(st, STATUS_IO_ERROR, 'cannot open ' // what // ' ' // path)
            return
        end if
        inquire (unit=unit, size=nbytes)
        if (nbytes > MAX_TEXT_FILE_BYTES) then
            close (unit)
            call set_error(st, STATUS_IO_ERROR, what // ' ' // path // ' has more than ' // &
                '2**31 - 1 bytes')
            return
        end if
        deallocate (text)
        allocate (character(len=max(nbytes, 0_i8)) :: text, stat=ios)
        if (ios /= 0) then
            close (unit)
            call set_error(st, STATUS_IO_ERROR, what // ' ' // path // ': not enough ' // &
                'memory to read its bytes')
            return
        end if
        msg = ''
        if (nbytes > 0) read (unit, iostat=ios, iomsg=msg) text
        close (unit)
        if (ios /= 0) call set_error(st, STATUS_IO_ERROR, 'cannot read ' // what // ' ' // &
            path // ': ' // trim(msg))
    end subroutine read_text_file

    !> The lines of `text` (without their LF, or CR LF, ends).
    subroutine split_text_lines(text, lines)
        character(len=*), intent(in) :: text
        type(string_t), allocatable, intent(out) :: lines(:)
        integer :: n, k, start, i, last
        n = 0
        do k = 1, len(text)
            if (text(k:k) == achar(10)) n = n + 1
        end do
        if (len(text) > 0) then
            if (text(len(text):len(text)) /= achar(10)) n = n + 1
        end if
        allocate (lines(n))
        start = 1
        i = 0
        do k = 1, len(text) + 1
            if (k <= len(text)) then
                if (text(k:k) /= achar(10)) cycle
            else if (start > len(text)) then
                exit
            end if
            i = i + 1
            last = k - 1
            if (last >= start) then
                if (text(last:last) == achar(13)) last = last - 1
            end if
            lines(i)%s = text(start:last)
            start = k + 1
        end do
    end subroutine split_text_lines

end module text_file
