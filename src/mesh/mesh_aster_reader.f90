!> Reader of Code_Aster native meshes (.mail, LIRE_MAILLAGE FORMAT='ASTER').
!>
!> A .mail file is a sequence of sub-files, each opened by a keyword line and closed by
!> FINSF, the whole ended by FIN:
!>   TITRE ... FINSF              free text
!>   COOR_2D | COOR_3D            one node per line: name x y [z]
!>   POI1 | SEG2 | SEG3 | TRIA3 | TRIA6 | QUAD4 | QUAD8 | QUAD9
!>                                one cell per line: name node... (Code_Aster's node order)
!>   GROUP_NO | GROUP_MA          name (`NOM=NAME` on the header line, or first token of the
!>                                next line), then member names over any number of lines
!> `%` starts a comment; blanks and commas separate tokens; other `KEY=VALUE` tokens on a
!> header line (NBOBJ=, AUTEUR=, ...) are accepted and ignored. Names must be defined
!> before they are used (nodes before cells, cells before groups), as every mesher does.
module mesh_aster_reader
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MESH_ERROR
    use strings, only: to_upper, to_text
    use number_limits, only: MAX_LENGTH
    use mesh_name_index, only: name_find
    use mesh_types, only: mesh_t, mesh_init, mesh_add_node, mesh_add_cell, &
        mesh_add_node_group, mesh_add_cell_group, mesh_finish, not_found_message, &
        CELL_TYPE_NAMES, CELL_TYPE_NODES, N_CELL_TYPES, ENTITY_NODE, ENTITY_CELL
    use mesh_text_lexer, only: text_lexer_t, open_lexer, next_token, next_line, at_end, &
        parse_real
    implicit none
    private

    public :: read_aster_mesh, read_aster_text

    !> Cell types that Code_Aster knows and parasol refuses by name.
    character(len=7), parameter :: OTHER_CELL_TYPES(12) = ['SEG4   ', 'TRIA7  ', &
        'TETRA4 ', 'TETRA10', 'PENTA6 ', 'PENTA15', 'PENTA18', 'HEXA8  ', 'HEXA20 ', &
        'HEXA27 ', 'PYRAM5 ', 'PYRAM13']
    !> The cell types parasol reads, for messages.
    character(len=*), parameter :: KNOWN_CELL_TYPES = &
        'POI1, SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9'

contains

    !> Reads the .mail file `path` into `mesh`.
    !>  path : in, file name (also used in messages as `path:LINE: ...`)
    !>  mesh : out, the mesh (dimension from COOR_2D/COOR_3D)
    !>  st   : out, STATUS_IO_ERROR if unreadable; STATUS_MESH_ERROR with file and line for
    !>         unknown sub-file keyword, unsupported cell type, duplicate or unknown name,
    !>         wrong value count, bad number, degenerate cell, empty mesh, missing FIN.
    subroutine read_aster_mesh(path, mesh, st)
        character(len=*), intent(in) :: path
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        type(text_lexer_t) :: lex
        call open_lexer(lex, path, st)
        if (st%failed()) return
        call read_lexer(lex, mesh, st)
    end subroutine read_aster_mesh

    !> Reads .mail text held in memory (what PRE_GIBI makes of a GIBI file) into `mesh`.
    !>  name : in, what messages call the text (`name:LINE: ...`) and mesh%file
    subroutine read_aster_text(text, name, mesh, st)
        character(len=*), intent(in) :: text, name
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(out) :: st
        type(text_lexer_t) :: lex
        lex%text = text
        lex%file = name
        call read_lexer(lex, mesh, st)
    end subroutine read_aster_text

    ! The sub-files of `lex` to FIN, then the mesh checked (mesh_finish).
    subroutine read_lexer(lex, mesh, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(out) :: mesh
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last, dim
        logical :: found_fin
        character(len=:), allocatable :: word
        call mesh_init(mesh, 3_i4, lex%file)
        dim = 0
        found_fin = .false.
        do while (.not. at_end(lex))
            call next_token(lex, first, last)
            if (first == 0) then
                call next_line(lex)
                cycle
            end if
            word = to_upper(lex%text(first:last))
            if (word == 'FIN') then
                found_fin = .true.
                exit
            end if
            call read_sub_file(lex, mesh, word, dim, st)
            if (st%failed()) return
        end do
        if (.not. found_fin) then
            call set_error(st, STATUS_MESH_ERROR, 'no FIN at the end of the mesh file ' // &
                '(the file is truncated?)', file=lex%file, line=lex%line)
            return
        end if
        mesh%dim = max(dim, 2_i4)
        call mesh_finish(mesh, lex%line, st)
    end subroutine read_lexer

    ! Dispatches on the sub-file keyword `word` (already consumed) and reads to FINSF.
    subroutine read_sub_file(lex, mesh, word, dim, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        character(len=*), intent(in) :: word
        integer(i4), intent(inout) :: dim
        type(status_t), intent(inout) :: st
        integer(i4) :: t
        select case (word)
        case ('TITRE')
            call read_title(lex, mesh)
        case ('COOR_2D', 'COOR_3D')
            dim = merge(2_i4, 3_i4, word == 'COOR_2D')
            call read_nodes(lex, mesh, dim, st)
        case ('GROUP_NO', 'GROUP_MA')
            call read_group(lex, mesh, word == 'GROUP_NO', st)
        case default
            do t = 1, N_CELL_TYPES
                if (word == trim(CELL_TYPE_NAMES(t))) then
                    call read_cells(lex, mesh, t, st)
                    return
                end if
            end do
            if (any(word == OTHER_CELL_TYPES)) then
                call set_error(st, STATUS_MESH_ERROR, 'cell type ' // word // &
                    ' is not supported (' // KNOWN_CELL_TYPES // ')', file=mesh%file, &
                    line=lex%line)
            else
                call set_error(st, STATUS_MESH_ERROR, 'unknown sub-file keyword ' // word // &
                    ' (expected TITRE, COOR_2D, COOR_3D, ' // KNOWN_CELL_TYPES // &
                    ', GROUP_NO, GROUP_MA or FIN)', file=mesh%file, line=lex%line)
            end if
        end select
    end subroutine read_sub_file

    ! True if the next line starts with FINSF (consumed with its line); else the lexer is
    ! left at the first token of the line (first/last set), skipping empty lines.
    logical function at_finsf(lex, first, last) result(done)
        type(text_lexer_t), intent(inout) :: lex
        integer(i4), intent(out) :: first, last
        done = .false.
        do
            call next_token(lex, first, last)
            if (first > 0) exit
            if (at_end(lex)) return
            call next_line(lex)
        end do
        if (to_upper(lex%text(first:last)) == 'FINSF') then
            done = .true.
            call next_line(lex)
        end if
    end function at_finsf

    subroutine read_title(lex, mesh)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        integer(i4) :: first, last
        call next_line(lex)
        do while (.not. at_end(lex))
            if (at_finsf(lex, first, last)) return
            if (len(mesh%title) == 0) then
                mesh%title = lex%text(first:last)
                do
                    call next_token(lex, first, last)
                    if (first == 0) exit
                    mesh%title = mesh%title // ' ' // lex%text(first:last)
                end do
            end if
            call next_line(lex)
        end do
    end subroutine read_title

    ! COOR_nD: `name x y [z]` per line until FINSF.
    subroutine read_nodes(lex, mesh, dim, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: dim
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last, f2, l2, k, name_first, name_last
        real(dp) :: xyz(3)
        logical :: ok, huge_value
        call next_line(lex)
        do while (.not. at_end(lex))
            if (at_finsf(lex, first, last)) return
            name_first = first
            name_last = last
            xyz = 0.0_dp
            do k = 1, dim + 1
                call next_token(lex, f2, l2)
                if (f2 == 0 .and. k <= dim) then
                    call set_error(st, STATUS_MESH_ERROR, 'node ' // &
                        lex%text(name_first:name_last) // ' has ' // achar(47 + k) // &
                        ' coordinates, COOR_' // achar(48 + dim) // 'D needs ' // achar(48 + dim), &
                        file=mesh%file, line=lex%line)
                    return
                else if (k > dim) then
                    if (f2 /= 0) call set_error(st, STATUS_MESH_ERROR, 'node ' // &
                        lex%text(name_first:name_last) // ' has more than ' // &
                        achar(48 + dim) // ' coordinates (COOR_' // achar(48 + dim) // 'D)', &
                        file=mesh%file, line=lex%line)
                    exit
                end if
                call parse_real(lex%text(f2:l2), xyz(k), ok, huge_value)
                if (huge_value) then
                    call set_error(st, STATUS_MESH_ERROR, 'node ' // &
                        lex%text(name_first:name_last) // ': coordinate "' // &
                        lex%text(f2:l2) // '" is out of range (|x| <= ' // &
                        to_text(MAX_LENGTH) // ')', file=mesh%file, line=lex%line)
                    return
                else if (.not. ok) then
                    call set_error(st, STATUS_MESH_ERROR, 'node ' // &
                        lex%text(name_first:name_last) // ': "' // lex%text(f2:l2) // &
                        '" is not a real number', file=mesh%file, line=lex%line)
                    return
                end if
            end do
            if (st%failed()) return
            call mesh_add_node(mesh, lex%text(name_first:name_last), xyz, lex%line, st)
            if (st%failed()) return
            call next_line(lex)
        end do
        call missing_finsf(lex, mesh, st)
    end subroutine read_nodes

    ! Cells of type `ctype`: `name node...` per line until FINSF.
    subroutine read_cells(lex, mesh, ctype, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        integer(i4), intent(in) :: ctype
        type(status_t), intent(inout) :: st
        integer(i4) :: first, last, f2, l2, n, nodes(64), line
        character(len=:), allocatable :: name
        call next_line(lex)
        do while (.not. at_end(lex))
            if (at_finsf(lex, first, last)) return
            name = lex%text(first:last)
            line = lex%line
            n = 0
            do
                call next_token(lex, f2, l2)
                if (f2 == 0) then
                    ! a cell's nodes may go on over the next lines (Code_Aster's free
                    ! format: QUAD8 and longer cells are often written on two lines)
                    if (n >= CELL_TYPE_NODES(ctype)) exit
                    if (.not. continues(lex)) exit
                    cycle
                end if
                n = n + 1
                if (n > size(nodes)) exit
                nodes(n) = name_find(mesh%node_names, lex%text(f2:l2))
                if (nodes(n) == 0) then
                    call set_error(st, STATUS_MESH_ERROR, 'cell ' // name // &
                        ': ' // not_found_message(mesh, mesh%node_names, ENTITY_NODE, &
                        lex%text(f2:l2)), file=mesh%file, line=lex%line)
                    return
                end if
            end do
            call mesh_add_cell(mesh, name, ctype, nodes(1:min(n, 64)), line, st)
            if (st%failed()) return
            call next_line(lex)
        end do
        call missing_finsf(lex, mesh, st)
    contains
        ! Moves to the next line when it goes on with the cell's nodes: not the end of the
        ! text nor a FINSF line (blank and comment lines are skipped). Else the lexer stays.
        logical function continues(lex) result(more)
            type(text_lexer_t), intent(inout) :: lex
            integer(i4) :: f3, l3, saved_pos, saved_line
            saved_pos = lex%pos
            saved_line = lex%line
            more = .false.
            do
                call next_line(lex)
                if (at_end(lex)) exit
                call next_token(lex, f3, l3)
                if (f3 == 0) cycle
                more = to_upper(lex%text(f3:l3)) /= 'FINSF'
                lex%pos = f3           ! the token is read again by the caller
                exit
            end do
            if (more) return
            lex%pos = saved_pos
            lex%line = saved_line
        end function continues
    end subroutine read_cells

    ! GROUP_NO / GROUP_MA: name from NOM= on the header line or first token of the next
    ! line, then member names until FINSF.
    subroutine read_group(lex, mesh, of_nodes, st)
        type(text_lexer_t), intent(inout) :: lex
        type(mesh_t), intent(inout) :: mesh
        logical, intent(in) :: of_nodes
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: name, message
        integer(i4), allocatable :: members(:)
        integer(i4) :: first, last, n, header_line, k
        header_line = lex%line
        name = header_name(lex)
        call next_line(lex)
        if (len(name) == 0) then
            if (at_finsf(lex, first, last)) then
                call set_error(st, STATUS_MESH_ERROR, 'group without a name', &
                               file=mesh%file, line=header_line)
                return
            end if
            name = lex%text(first:last)
            header_line = lex%line
            ! members may follow the name on its line (PRE_GIBI writes `A  N1`)
            call next_token(lex, first, last)
        else
            first = 0
        end if
        allocate (members(64))
        n = 0
        do while (.not. at_end(lex))
            if (first == 0) then   ! a new line (else: the rest of the name's line)
                if (at_finsf(lex, first, last)) then
                    if (of_nodes) then
                        call mesh_add_node_group(mesh, name, members(1:n), header_line, st)
                    else
                        call mesh_add_cell_group(mesh, name, members(1:n), header_line, st)
                    end if
                    return
                end if
            end if
            do while (first > 0)
                if (n == size(members)) members = [members, members]
                n = n + 1
                if (of_nodes) then
                    k = name_find(mesh%node_names, lex%text(first:last))
                else
                    k = name_find(mesh%cell_names, lex%text(first:last))
                end if
                if (k == 0) then
                    if (of_nodes) then
                        message = not_found_message(mesh, mesh%node_names, ENTITY_NODE, &
                                                    lex%text(first:last))
                    else
                        message = not_found_message(mesh, mesh%cell_names, ENTITY_CELL, &
                                                    lex%text(first:last))
                    end if
                    call set_error(st, STATUS_MESH_ERROR, trim(merge('GROUP_NO', 'GROUP_MA', &
                        of_nodes)) // ' ' // name // ': ' // message, file=mesh%file, line=lex%line)
                    return
                end if
                members(n) = k
                call next_token(lex, first, last)
            end do
            call next_line(lex)
        end do
        call missing_finsf(lex, mesh, st)
    end subroutine read_group

    ! Name given as NOM=NAME (or NOM= NAME) on the rest of the header line, else ''.
    function header_name(lex) result(name)
        type(text_lexer_t), intent(inout) :: lex
        character(len=:), allocatable :: name
        integer(i4) :: first, last
        name = ''
        do
            call next_token(lex, first, last)
            if (first == 0) return
            if (to_upper(lex%text(first:min(first + 3, last))) /= 'NOM=') cycle
            if (last > first + 3) then
                name = lex%text(first + 4:last)
            else
                call next_token(lex, first, last)
                if (first > 0) name = lex%text(first:last)
            end if
            return
        end do
    end function header_name

    subroutine missing_finsf(lex, mesh, st)
        type(text_lexer_t), intent(in) :: lex
        type(mesh_t), intent(in) :: mesh
        type(status_t), intent(inout) :: st
        call set_error(st, STATUS_MESH_ERROR, 'end of file inside a sub-file: FINSF ' // &
                       'and FIN are missing', file=mesh%file, line=lex%line)
    end subroutine missing_finsf

end module mesh_aster_reader
