!> Gmsh's first mesh format (1.0: sections $NOD ... $ENDNOD and $ELM ... $ENDELM, no
!> $MeshFormat), as Code_Aster's PRE_GMSH still reads it (ssls128a.msh), turned into the
!> 2.2 text mesh_gmsh_reader reads, line for line:
!>   $NOD / $ENDNOD            -> $Nodes / $EndNodes (the node lines are the same)
!>   $ELM / $ENDELM            -> $Elements / $EndElements
!>   elm type phys elem n nodes -> elm type 2 phys elem nodes (2.2 gives the tag count and
!>                                 takes the node count from the type; the physical number
!>                                 is the first tag, as in 1.0)
!> with a 3-line $MeshFormat (2.2 0 8) in front; the caller starts counting lines at -2 so
!> that errors keep the 1.0 file's line numbers. A node count that is not the type's
!> (for the types parasol reads) is an error at its line.
module mesh_gmsh1_text
    use kinds, only: i4
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: string_t, to_text
    use text_file, only: split_text_lines
    use mesh_text_lexer, only: parse_integer
    implicit none
    private

    public :: is_gmsh1, gmsh1_to_gmsh22

    !> The lines of the 2.2 header put in front (the caller's line count starts below 1).
    integer(i4), parameter, public :: GMSH1_HEADER_LINES = 3

    !> Gmsh element types and their node counts (the types mesh_gmsh_reader reads).
    integer(i4), parameter :: KNOWN_TYPES(8) = [15, 1, 2, 3, 8, 9, 16, 10]
    integer(i4), parameter :: KNOWN_NODES(8) = [1, 2, 3, 4, 3, 6, 8, 9]

contains

    !> True when the first word of `text` is $NOD (the 1.0 format).
    logical function is_gmsh1(text)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: head
        head = adjustl(text(1:min(len(text), 64)))
        is_gmsh1 = .false.
        if (len(head) < 4) return
        if (head(1:4) /= '$NOD') return
        is_gmsh1 = len(head) == 4
        if (.not. is_gmsh1) is_gmsh1 = index(' ' // achar(9) // achar(10) // achar(13), &
                                             head(5:5)) > 0
    end function is_gmsh1

    !> The 2.2 text of the 1.0 text `text` of file `path` (module header).
    subroutine gmsh1_to_gmsh22(text, path, converted, st)
        character(len=*), intent(in) :: text, path
        character(len=:), allocatable, intent(out) :: converted
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: lines(:)
        character(len=:), allocatable :: line, word
        integer(i4), allocatable :: fields(:)
        integer(i4) :: k, j, n_words, in_elements, expected, t
        integer :: total
        logical :: ok
        call split_text_lines(text, lines)
        in_elements = 0
        total = 0
        do k = 1, size(lines, kind=i4)
            line = trim(adjustl(lines(k)%s))
            select case (line)
            case ('$NOD')
                lines(k)%s = '$Nodes'
            case ('$ENDNOD')
                lines(k)%s = '$EndNodes'
            case ('$ELM')
                lines(k)%s = '$Elements'
                in_elements = 1
            case ('$ENDELM')
                lines(k)%s = '$EndElements'
                in_elements = 0
            case default
                if (in_elements == 1) then
                    in_elements = 2        ! the element count
                else if (in_elements == 2 .and. len(line) > 0) then
                    call split_ints(line, fields, n_words, ok)
                    if (.not. ok .or. n_words < 5) then
                        call set_error(st, STATUS_MESH_ERROR, 'an element line of the 1.0 ' // &
                            'format is: number, type, physical, elementary, node count, ' // &
                            'nodes (integers)', file=path, line=k)
                        return
                    end if
                    t = findloc(KNOWN_TYPES, fields(2), dim=1)
                    expected = -1
                    if (t > 0) expected = KNOWN_NODES(t)
                    if (expected >= 0 .and. (fields(5) /= expected .or. &
                                             n_words - 5 /= expected)) then
                        call set_error(st, STATUS_MESH_ERROR, 'element ' // &
                            to_text(fields(1)) // ' of type ' // to_text(fields(2)) // &
                            ' lists ' // to_text(n_words - 5) // ' nodes (count ' // &
                            to_text(fields(5)) // '), the type has ' // to_text(expected), &
                            file=path, line=k)
                        return
                    end if
                    word = to_text(fields(1)) // ' ' // to_text(fields(2)) // ' 2 ' // &
                        to_text(fields(3)) // ' ' // to_text(fields(4))
                    do j = 6, n_words
                        word = word // ' ' // to_text(fields(j))
                    end do
                    lines(k)%s = word
                end if
            end select
            total = total + len(lines(k)%s) + 1
        end do
        converted = '$MeshFormat' // achar(10) // '2.2 0 8' // achar(10) // '$EndMeshFormat' &
            // achar(10) // repeat(' ', total)
        j = len(converted) - total + 1
        do k = 1, size(lines, kind=i4)     ! one pass (appending line by line is quadratic)
            converted(j:j + len(lines(k)%s)) = lines(k)%s // achar(10)
            j = j + len(lines(k)%s) + 1
        end do
    end subroutine gmsh1_to_gmsh22

    ! The integers of `line` (blank separated); ok false if a word is not one.
    subroutine split_ints(line, fields, n, ok)
        character(len=*), intent(in) :: line
        integer(i4), allocatable, intent(out) :: fields(:)
        integer(i4), intent(out) :: n
        logical, intent(out) :: ok
        integer(i4) :: p, q, value
        allocate (fields(len(line) / 2 + 1))
        n = 0
        ok = .true.
        p = 1
        do while (p <= len(line))
            if (line(p:p) == ' ' .or. line(p:p) == achar(9) .or. line(p:p) == achar(13)) then
                p = p + 1
                cycle
            end if
            q = p
            do while (q < len(line))
                if (line(q + 1:q + 1) == ' ' .or. line(q + 1:q + 1) == achar(9) .or. &
                    line(q + 1:q + 1) == achar(13)) exit
                q = q + 1
            end do
            call parse_integer(line(p:q), value, ok)
            if (.not. ok) return
            n = n + 1
            fields(n) = value
            p = q + 1
        end do
    end subroutine split_ints

end module mesh_gmsh1_text
