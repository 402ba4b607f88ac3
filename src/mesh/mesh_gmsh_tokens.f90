!> Token readers of the Gmsh reader (mesh_gmsh_reader): integers, counts checked against the
!> bytes left in the file, reals within the coordinate bound, expected words; each error
!> located at the lexer's line.
module mesh_gmsh_tokens
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_text
    use number_limits, only: MAX_LENGTH
    use mesh_text_lexer, only: text_lexer_t, next_token, next_line, at_end, parse_real, &
        parse_integer, bytes_left
    implicit none
    private

    public :: get_int, get_count, check_count, get_real, next_any, expect

contains

    ! Reads the next integer, across line ends unless same_line.
    subroutine get_int(lex, value, what, st, same_line)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: value
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        logical, intent(in), optional :: same_line
        integer(i4) :: first, last
        logical :: ok
        value = 0
        call next_any(lex, first, last, present(same_line))
        if (first == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'missing ' // what, line=lex%line)
            return
        end if
        call parse_integer(lex%text(first:last), value, ok)
        if (.not. ok) call set_error(st, STATUS_MESH_ERROR, what // ': "' // &
            lex%text(first:last) // '" is not an integer', line=lex%line)
    end subroutine get_int

    ! Reads a count of items taking at least `item_bytes` bytes each: an error when it is
    ! negative or more than the bytes left in the file can hold.
    subroutine get_count(lex, value, what, item_bytes, st, same_line)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: value
        character(len=*), intent(in) :: what
        integer(i8), intent(in) :: item_bytes
        type(status_t), intent(inout) :: st
        logical, intent(in), optional :: same_line
        if (present(same_line)) then
            call get_int(lex, value, what, st, same_line)
        else
            call get_int(lex, value, what, st)
        end if
        if (st%failed()) return
        call check_count(lex, value, what, item_bytes, st)
        if (st%failed()) value = 0
    end subroutine get_count

    subroutine check_count(lex, value, what, item_bytes, st)
        type(text_lexer_t), intent(in) :: lex
        integer(i4), intent(in) :: value
        character(len=*), intent(in) :: what
        integer(i8), intent(in) :: item_bytes
        type(status_t), intent(inout) :: st
        if (value < 0) then
            call set_error(st, STATUS_MESH_ERROR, what // ' = ' // to_text(value) // &
                ' is negative', line=lex%line)
        else if (int(value, i8) > bytes_left(lex) / item_bytes) then
            call set_error(st, STATUS_MESH_ERROR, what // ' = ' // to_text(value) // &
                ' is more than the ' // to_text(bytes_left(lex)) // ' bytes left in the ' // &
                'file can hold (at least ' // to_text(item_bytes) // ' bytes each)', &
                line=lex%line)
        end if
    end subroutine check_count

    subroutine get_real(lex, value, what, st)
        type(text_lexer_t), intent(inout) :: lex
        real(dp), intent(out) :: value
        character(len=*), intent(in) :: what
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last
        logical :: ok, huge_value
        value = 0.0_dp
        call next_any(lex, first, last, .false.)
        if (first == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'missing ' // what, line=lex%line)
            return
        end if
        call parse_real(lex%text(first:last), value, ok, huge_value)
        if (huge_value) then
            ! 1e308 or more: a coordinate's bound is MAX_LENGTH (mesh_add_node checks the
            ! rest), that of a number read and not used (bounding box, parameter) 1e308
            if (what == 'node coordinate') then
                call set_error(st, STATUS_MESH_ERROR, what // ': "' // lex%text(first:last) // &
                    '" is out of range (|x| <= ' // to_text(MAX_LENGTH) // ')', line=lex%line)
            else
                call set_error(st, STATUS_MESH_ERROR, what // ': "' // lex%text(first:last) // &
                    '" is out of range (|x| < 1E+308)', line=lex%line)
            end if
        else if (.not. ok) then
            call set_error(st, STATUS_MESH_ERROR, what // ': "' // lex%text(first:last) // &
                '" is not a real number', line=lex%line)
        end if
    end subroutine get_real

    subroutine next_any(lex, first, last, same_line)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: first, last
        logical, intent(in) :: same_line
        do
            call next_token(lex, first, last)
            if (first > 0 .or. same_line .or. at_end(lex)) return
            call next_line(lex)
        end do
    end subroutine next_any

    ! Expects the token `word` (a section end) as the next token.
    subroutine expect(lex, word, st)
        type(text_lexer_t), intent(inout) :: lex
        character(len=*), intent(in) :: word
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last
        call next_any(lex, first, last, .false.)
        if (first == 0) then
            call set_error(st, STATUS_MESH_ERROR, 'end of file: ' // word // ' is missing', &
                           line=lex%line)
        else if (lex%text(first:last) /= word) then
            call set_error(st, STATUS_MESH_ERROR, 'expected ' // word // ', found "' // &
                lex%text(first:last) // '" (wrong count in the section?)', line=lex%line)
        end if
    end subroutine expect

end module mesh_gmsh_tokens
