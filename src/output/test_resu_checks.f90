!> What every TEST_RESU occurrence shares (RESU, CHAM_NO, CHAM_ELEM, CARTE, MAILLAGE):
!> reading its checks (Code_Aster's C_TEST_REFERENCE keywords), finding the tested value in
!> a field (test_value_in_field: at a node, a cell's point and sub-point, or TYPE_TEST over
!> the field) and writing the block to the listings (listings.md, "TEST_RESU semantics").
module test_resu_checks
    use keyword_relocation, only: relocate => relocate_error
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: string_t, to_text, to_upper
    use deck_command, only: keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_node, find_cell, find_node_group, find_cell_group, &
        nodes_of_group, cells_of_group
    use field_types, only: field_t, FIELD_NOEU, FIELD_ELGA, FIELD_ELNO, field_is_cell_field, &
        field_node_value, field_cell_value, field_values_of, field_location_name
    use test_resu_format, only: test_check_t, test_check_block, TEST_RESU_ZERO, &
        TEST_RESU_DEFAULT_TOLE_MACHINE, TEST_RESU_DEFAULT_PRECISION, is_test_resu_criterion
    implicit none
    private

    !> Words written instead of the non-finite spellings NaN, +Inf, -Inf.
    character(len=*), parameter, public :: LISTING_NOT_FINITE = 'NON_FINI'
    character(len=*), parameter, public :: LISTING_PLUS_INFINITE = '+INFINI'
    character(len=*), parameter, public :: LISTING_MINUS_INFINITE = '-INFINI'

    !> The identification columns of a block, built up by the occurrence handlers.
    type, public :: test_columns_t
        type(string_t), allocatable :: titles(:), values(:)
    end type test_columns_t

    public :: read_checks, write_test_block, add_column, test_value_in_field, &
        listing_safe_text, compact_text, relocate, single_node, single_cell

contains

    !> Appends an identification column.
    subroutine add_column(cols, title, value)
        type(test_columns_t), intent(inout) :: cols
        character(len=*), intent(in) :: title, value
        type(string_t), allocatable :: titles(:), values(:)
        integer :: n, k
        n = 0
        if (allocated(cols%titles)) n = size(cols%titles)
        allocate (titles(n + 1), values(n + 1))
        do k = 1, n
            call move_alloc(cols%titles(k)%s, titles(k)%s)
            call move_alloc(cols%values(k)%s, values(k)%s)
        end do
        titles(n + 1)%s = title
        values(n + 1)%s = value
        call move_alloc(titles, cols%titles)
        call move_alloc(values, cols%values)
    end subroutine add_column

    !> The checks of an occurrence: NON_REGRESSION against VALE_CALC (VALE_CALC_I) at
    !> TOLE_MACHINE, then, with REFERENCE, the reference check against VALE_REFE
    !> (VALE_REFE_I) at PRECISION. CRITERE applies to both; TOLE_MACHINE and CRITERE may
    !> hold a second value (RESU: the precision and criterion of the instant), only the first
    !> is the test's. |VALE_CALC| <= TEST_RESU_ZERO without ORDRE_GRANDEUR skips the
    !> NON_REGRESSION check, as Code_Aster does; ORDRE_GRANDEUR scales an ABSOLU tolerance.
    !>  integers : out, the values are integers (VALE_CALC_I)
    !>  st       : located at the keyword (REFERENCE without VALE_REFE, a negative tolerance,
    !>             VALE_REFE and VALE_CALC of different counts)
    subroutine read_checks(occ, checks, integers, st)
        type(keyword_set_t), intent(in) :: occ
        type(test_check_t), allocatable, intent(out) :: checks(:)
        logical, intent(out) :: integers
        type(status_t), intent(out) :: st
        real(dp), allocatable :: tolerances(:), calc(:), refe(:)
        integer(i4), allocatable :: icalc(:), irefe(:)
        type(string_t), allocatable :: criteria(:)
        character(len=:), allocatable :: criterion, legend, kind, text
        real(dp) :: precision, magnitude
        logical :: with_reference, absolute_values
        integers = occ%has('VALE_CALC_I')
        if (integers) then
            call occ%get_ints('VALE_CALC_I', icalc, st)
            calc = real(icalc, dp)
        else
            call occ%get_reals('VALE_CALC', calc, st)
        end if
        if (st%failed()) return
        tolerances = [TEST_RESU_DEFAULT_TOLE_MACHINE]
        if (occ%has('TOLE_MACHINE')) call occ%get_reals('TOLE_MACHINE', tolerances, st)
        criterion = 'RELATIF'
        if (st%ok() .and. occ%has('CRITERE')) then
            call occ%get_texts('CRITERE', criteria, st)
            if (st%ok()) criterion = to_upper(criteria(1)%s)
        end if
        if (st%failed()) return
        if (.not. is_test_resu_criterion(criterion)) then
            call occ%error_at('CRITERE', 'RELATIF or ABSOLU, not ' // criterion, st)
            return
        end if
        if (any(tolerances < 0.0_dp)) then
            call occ%error_at('TOLE_MACHINE', 'a tolerance must be >= 0', st)
            return
        end if
        legend = ''
        if (occ%has('LEGENDE')) call occ%get_text('LEGENDE', legend, st)
        absolute_values = .false.
        if (st%ok() .and. occ%has('VALE_ABS')) then
            call occ%get_text('VALE_ABS', text, st)
            absolute_values = text == 'OUI'
        end if
        magnitude = 1.0_dp
        if (st%ok() .and. occ%has('ORDRE_GRANDEUR')) call occ%get_real('ORDRE_GRANDEUR', &
            magnitude, st)
        if (st%failed()) return
        with_reference = occ%has('REFERENCE')
        if (with_reference .neqv. (occ%has('VALE_REFE') .or. occ%has('VALE_REFE_I'))) then
            call occ%error_at(trim(merge('REFERENCE', 'VALE_REFE', with_reference)), &
                'REFERENCE and VALE_REFE go together (give both or neither)', st)
            return
        end if
        allocate (checks(merge(2, 1, with_reference)))
        checks(1)%kind = 'NON_REGRESSION'
        checks(1)%legend = ''
        checks(1)%criterion = criterion
        checks(1)%references = calc
        checks(1)%tolerance = tolerances(1)
        checks(1)%magnitude = magnitude
        checks(1)%absolute_values = absolute_values
        checks(1)%integers = integers
        checks(1)%skip = .not. integers .and. .not. occ%has('ORDRE_GRANDEUR') .and. &
            all(abs(calc) <= TEST_RESU_ZERO)
        if (.not. with_reference) return
        call occ%get_text('REFERENCE', kind, st)
        if (st%failed()) return
        if (occ%has('VALE_REFE_I')) then
            call occ%get_ints('VALE_REFE_I', irefe, st)
            refe = real(irefe, dp)
        else
            call occ%get_reals('VALE_REFE', refe, st)
        end if
        precision = TEST_RESU_DEFAULT_PRECISION
        if (st%ok() .and. occ%has('PRECISION')) call occ%get_real('PRECISION', precision, st)
        if (st%failed()) return
        if (precision < 0.0_dp) then
            call occ%error_at('PRECISION', 'a tolerance must be >= 0', st)
            return
        end if
        if (size(refe) /= size(calc)) then
            call occ%error_at('VALE_REFE', 'give as many VALE_REFE as VALE_CALC (' // &
                to_text(size(calc)) // ')', st)
            return
        end if
        checks(2)%kind = kind
        checks(2)%legend = legend
        checks(2)%criterion = criterion
        checks(2)%references = refe
        checks(2)%tolerance = precision
        checks(2)%absolute_values = absolute_values
        checks(2)%integers = integers
    end subroutine read_checks

    !> Builds the block of a tested value and writes it: to the .resu, each check line in
    !> compact form to the .mess, the verdicts counted in the run context (a skipped check
    !> counts in neither).
    !>  label : in, optional, the command the .mess echo names (default TEST_RESU)
    subroutine write_test_block(ctx, cols, checks, computed, label)
        type(run_context_t), intent(inout) :: ctx
        type(test_columns_t), intent(in) :: cols
        type(test_check_t), intent(in) :: checks(:)
        real(dp), intent(in) :: computed
        character(len=*), intent(in), optional :: label
        type(string_t), allocatable :: lines(:)
        integer :: n_ok, n_nook, k
        character(len=:), allocatable :: id, command
        command = 'TEST_RESU'
        if (present(label)) command = label
        n_ok = 0
        n_nook = 0
        call test_check_block(cols%titles, cols%values, checks, computed, lines, n_ok, n_nook)
        do k = 1, size(lines)
            call ctx%write_resu(listing_safe_text(lines(k)%s))
        end do
        id = compact_text(lines(2)%s)
        do k = 4, size(lines)
            if (lines(k)%s(1:4) == ' OK ' .or. lines(k)%s(1:4) == 'NOOK') &
                call ctx%count_test(lines(k)%s(1:4) == ' OK ')
            call ctx%write_mess('    ' // command // ' ' // id // ': ' // &
                                listing_safe_text(compact_text(lines(k)%s)))
        end do
    end subroutine write_test_block

    !> The tested value of a field for an occurrence, and the columns that say where:
    !>  TYPE_TEST (MIN, MAX, SOMM, SOMM_ABS) over the field's values (of NOM_CMP when given);
    !>  a NOEU field at NOEUD or GROUP_NO (a group of one node);
    !>  a cell field at MAILLE or GROUP_MA (a group of one cell), and
    !>    ELGA: POINT (the Gauss point) and SOUS_POINT (default 1),
    !>    ELNO: the cell's node NOEUD / GROUP_NO, or POINT (its position in the cell),
    !>    ELEM, CART: the cell's value.
    !>  field_word : in, how messages name the field (e.g. 'SIGM_ELNO')
    !>  component  : in, NOM_CMP ('' with TYPE_TEST over every component)
    !>  st         : located at the keyword at fault, naming what exists
    subroutine test_value_in_field(ctx, occ, f, mesh, field_word, component, cols, value, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(field_t), intent(in) :: f
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: field_word, component
        type(test_columns_t), intent(inout) :: cols
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: cell_key, node_key, name, text
        integer(i4) :: cell, node, point, subpoint
        value = 0.0_dp
        if (occ%has('TYPE_TEST')) then
            call type_test_value(ctx, occ, f, component, cols, value, st)
            return
        end if
        if (len(component) == 0) then
            call occ%error_at('NOM_CMP', 'give NOM_CMP (or TYPE_TEST for the whole field)', st)
            return
        end if
        node_key = ''
        if (occ%has('GROUP_NO')) node_key = 'GROUP_NO'
        if (occ%has('NOEUD')) node_key = 'NOEUD'
        cell_key = ''
        if (occ%has('GROUP_MA')) cell_key = 'GROUP_MA'
        if (occ%has('MAILLE')) cell_key = 'MAILLE'
        if (f%location == FIELD_NOEU) then
            ! a cell with the node (Code_Aster's decks give GROUP_MA with GROUP_NO on a
            ! *_NOEU field, as for the *_ELNO lines around it): the node alone locates
            ! the value, the cell is not read (Code_Aster reads a nodal field at the node)
            if (len(cell_key) > 0 .and. len(node_key) == 0) then
                call occ%error_at(cell_key, field_word // ' is a nodal field: give GROUP_NO ' &
                    // 'or NOEUD', st)
                return
            end if
            if (occ%has('POINT')) then
                call occ%error_at('POINT', 'POINT goes with the element fields; ' // &
                    field_word // ' is read at a node', st)
                return
            end if
            if (len(node_key) == 0) then
                call occ%error_at(field_key(occ), field_word // ' is a nodal field: give ' // &
                    'GROUP_NO or NOEUD', st)
                return
            end if
            call located_node(occ, node_key, mesh, node, name, st)
            if (st%failed()) return
            call add_column(cols, node_key, name)
            call field_node_value(f, node, component, value, st)
            if (st%failed()) then
                st%message = 'node ' // name // ': ' // st%message
                call relocate(occ, 'NOM_CMP', st)
            end if
            return
        end if
        if (.not. field_is_cell_field(f)) then
            call occ%error_at('NOM_CMP', field_word // ' is an empty field', st)
            return
        end if
        if (len(cell_key) == 0) then
            if (len(node_key) > 0) then
                call occ%error_at(node_key, field_word // ' is an element field: give ' // &
                    'GROUP_MA (a group of one cell) or MAILLE' // point_hint(f), st)
            else
                call occ%error_at(field_key(occ), field_word // ' is an element field: give ' // &
                    'GROUP_MA (a group of one cell) or MAILLE' // point_hint(f), st)
            end if
            return
        end if
        call located_cell(occ, cell_key, mesh, cell, name, st)
        if (st%failed()) return
        call add_column(cols, cell_key, name)
        point = 1
        subpoint = 1
        if (f%location == FIELD_ELNO .and. len(node_key) > 0) then
            call located_node(occ, node_key, mesh, node, text, st)
            if (st%failed()) return
            point = position_in_cell(mesh, cell, node)
            if (point == 0) then
                call occ%error_at(node_key, 'node ' // text // ' is not a node of cell ' // &
                    name // ' (' // field_word // ' is read at a node of the cell)', st, &
                    STATUS_MODEL_ERROR)
                return
            end if
            call add_column(cols, node_key, text)
        else if (len(node_key) > 0) then
            call occ%error_at(node_key, field_word // ' is an ' // field_location_name(f) // &
                ' field: a node goes with ELNO fields only' // point_hint(f), st)
            return
        end if
        if (occ%has('POINT')) then
            call occ%get_int('POINT', point, st)
            if (st%failed()) return
            call add_column(cols, 'POINT', to_text(point))
        else if (f%location == FIELD_ELGA) then
            call occ%error_at(field_key(occ), field_word // ' is read at a Gauss point: give ' // &
                'POINT (1 to ' // to_text(f%n_points(cell)) // ' on cell ' // name // ')', st)
            return
        end if
        if (occ%has('SOUS_POINT')) then
            call occ%get_int('SOUS_POINT', subpoint, st)
            if (st%failed()) return
            call add_column(cols, 'SOUS_POINT', to_text(subpoint))
        else if (f%n_points(cell) > 0 .and. f%n_subpoints(cell) > 1) then
            call occ%error_at(field_key(occ), field_word // ' has ' // &
                to_text(f%n_subpoints(cell)) // ' sub-points (plate layers) on cell ' // &
                name // ': give SOUS_POINT', st)
            return
        end if
        call field_cell_value(f, cell, point, subpoint, component, value, st)
        if (st%failed()) then
            st%message = 'cell ' // name // ': ' // st%message
            if (index(st%message, 'POINT ') > 0 .and. index(st%message, 'SOUS_POINT') == 0) &
                then
                call relocate(occ, 'POINT', st)
            else if (index(st%message, 'SOUS_POINT') > 0) then
                call relocate(occ, 'SOUS_POINT', st)
            else if (index(st%message, 'no value on the cell') > 0) then
                call relocate(occ, cell_key, st)
            else
                call relocate(occ, 'NOM_CMP', st)
            end if
        end if
    end subroutine test_value_in_field

    !> The keyword that names the field of an occurrence (NOM_CHAM of RESU, CHAM_GD of a
    !> field occurrence): where "this field needs a location" is reported.
    function field_key(occ) result(key)
        type(keyword_set_t), intent(in) :: occ
        character(len=:), allocatable :: key
        key = 'CHAM_GD'
        if (occ%has('NOM_CHAM')) key = 'NOM_CHAM'
    end function field_key

    !> ' and POINT' for the fields read at points (messages).
    pure function point_hint(f) result(text)
        type(field_t), intent(in) :: f
        character(len=:), allocatable :: text
        text = ''
        if (f%location == FIELD_ELGA) text = ', and POINT'
        if (f%location == FIELD_ELNO) text = ', and the node (GROUP_NO, NOEUD) or POINT'
    end function point_hint

    !> TYPE_TEST over the field: MIN, MAX, SOMM (sum) or SOMM_ABS (sum of |values|) of
    !> every value (of NOM_CMP when given) at every node, or every point and sub-point of
    !> every cell. As Code_Aster, a node or cell given with it is ignored (a warning).
    subroutine type_test_value(ctx, occ, f, component, cols, value, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: component
        type(test_columns_t), intent(inout) :: cols
        real(dp), intent(out) :: value
        type(status_t), intent(out) :: st
        character(len=:), allocatable :: kind, file, key
        real(dp), allocatable :: values(:)
        integer :: line, col, k
        character(len=8), parameter :: IGNORED(4) = ['GROUP_NO', 'NOEUD   ', 'GROUP_MA', &
            'MAILLE  ']
        value = 0.0_dp
        call occ%get_text('TYPE_TEST', kind, st)
        if (st%failed()) return
        do k = 1, size(IGNORED)
            key = trim(IGNORED(k))
            if (.not. occ%has(key)) cycle
            call occ%location(key, file, line, col)
            call ctx%write_warning(file // ':' // to_text(line) // ':' // to_text(col) // &
                ': warning: TEST_RESU/' // key // ': ignored with TYPE_TEST (the test ' // &
                'is over the whole field, as in Code_Aster)')
        end do
        if (len(component) > 0) then
            call field_values_of(f, values, st, names=[string_t(component)])
        else
            call field_values_of(f, values, st)
        end if
        if (st%failed()) then
            call relocate(occ, 'NOM_CMP', st)
            return
        end if
        if (size(values) == 0) then
            call occ%error_at('TYPE_TEST', 'the field holds no value' // &
                trim(merge(' of ' // component, '   ' // component, len(component) > 0)) // &
                ' to test', st, STATUS_MODEL_ERROR)
            return
        end if
        if (kind == 'SOMM' .or. kind == 'SOMM_ABS') then
            ! a sum of n terms below 2**e stays below n 2**e: refuse what could overflow
            if (exponent(maxval(abs(values))) + exponent(real(size(values), dp)) > &
                maxexponent(1.0_dp) - 2) then
                call occ%error_at('TYPE_TEST', 'the sum of the field''s values is beyond ' // &
                    'double precision', st, STATUS_MODEL_ERROR)
                return
            end if
        end if
        select case (kind)
        case ('MIN')
            value = minval(values)
        case ('MAX')
            value = maxval(values)
        case ('SOMM')
            value = sum(values)
        case ('SOMM_ABS')
            value = sum(abs(values))
        end select
        call add_column(cols, 'TYPE_TEST', kind)
    end subroutine type_test_value

    !> The node named by NOEUD, or the one node of GROUP_NO.
    subroutine located_node(occ, key, mesh, node, name, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(out) :: node
        character(len=:), allocatable, intent(out) :: name
        type(status_t), intent(out) :: st
        node = 0
        call occ%get_text(key, name, st)
        if (st%failed()) return
        if (key == 'GROUP_NO') then
            call single_node(mesh, name, node, st)
        else
            node = find_node(mesh, name, st)
        end if
        if (st%failed()) call relocate(occ, key, st)
    end subroutine located_node

    !> The cell named by MAILLE, or the one cell of GROUP_MA.
    subroutine located_cell(occ, key, mesh, cell, name, st)
        type(keyword_set_t), intent(in) :: occ
        character(len=*), intent(in) :: key
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(out) :: cell
        character(len=:), allocatable, intent(out) :: name
        type(status_t), intent(out) :: st
        cell = 0
        call occ%get_text(key, name, st)
        if (st%failed()) return
        if (key == 'GROUP_MA') then
            call single_cell(mesh, name, cell, st)
        else
            cell = find_cell(mesh, name, st)
        end if
        if (st%failed()) call relocate(occ, key, st)
    end subroutine located_cell

    !> Position (1..) of `node` among the nodes of `cell`, 0 if it is not one of them.
    pure integer(i4) function position_in_cell(mesh, cell, node) result(k)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cell, node
        integer(i4) :: p
        k = 0
        do p = mesh%cell_ptr(cell), mesh%cell_ptr(cell + 1) - 1
            if (mesh%cell_nodes(p) == node) then
                k = p - mesh%cell_ptr(cell) + 1
                return
            end if
        end do
    end function position_in_cell

    !> The one node of GROUP_NO `group`.
    !>  st : STATUS_MODEL_ERROR when the group does not exist (with a did-you-mean) or does
    !>       not hold exactly one node (naming the group and its size)
    subroutine single_node(mesh, group, node, st)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: group
        integer(i4), intent(out) :: node
        type(status_t), intent(out) :: st
        integer(i4) :: g
        integer(i4), allocatable :: members(:)
        node = 0
        g = find_node_group(mesh, group, st)
        if (st%failed()) return
        members = nodes_of_group(mesh, g)
        if (size(members) /= 1) then
            call set_error(st, STATUS_MODEL_ERROR, 'GROUP_NO ' // group // ' holds ' // &
                           to_text(size(members, kind=i4)) // &
                           ' nodes; TEST_RESU needs a group of exactly one node (or NOEUD)')
            return
        end if
        node = members(1)
    end subroutine single_node

    !> The one cell of GROUP_MA `group`.
    !>  st : STATUS_MODEL_ERROR when the group does not exist (with a did-you-mean) or does
    !>       not hold exactly one cell (naming the group and its size)
    subroutine single_cell(mesh, group, cell, st)
        type(mesh_t), intent(in) :: mesh
        character(len=*), intent(in) :: group
        integer(i4), intent(out) :: cell
        type(status_t), intent(out) :: st
        integer(i4) :: g
        integer(i4), allocatable :: members(:)
        cell = 0
        g = find_cell_group(mesh, group, st)
        if (st%failed()) return
        members = cells_of_group(mesh, g)
        if (size(members) /= 1) then
            call set_error(st, STATUS_MODEL_ERROR, 'GROUP_MA ' // group // ' holds ' // &
                           to_text(size(members, kind=i4)) // &
                           ' cells; TEST_RESU needs a group of exactly one cell (or MAILLE)')
            return
        end if
        cell = members(1)
    end subroutine single_cell

    !> `text` with the non-finite spellings NaN, +Inf, -Inf (whole tokens, optionally
    !> followed by %) replaced by NON_FINI, +INFINI, -INFINI.
    pure function listing_safe_text(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        integer :: i, j
        character(len=:), allocatable :: token, core
        out = ''
        i = 1
        do while (i <= len(text))
            if (text(i:i) == ' ') then
                out = out // ' '
                i = i + 1
                cycle
            end if
            j = i
            do while (j < len(text))
                if (text(j + 1:j + 1) == ' ') exit
                j = j + 1
            end do
            token = text(i:j)
            core = token
            if (len(core) > 1) then
                if (core(len(core):) == '%') core = core(1:len(core) - 1)
            end if
            select case (core)
            case ('NaN')
                token = LISTING_NOT_FINITE // token(len(core) + 1:)
            case ('+Inf', 'Inf')
                token = LISTING_PLUS_INFINITE // token(len(core) + 1:)
            case ('-Inf')
                token = LISTING_MINUS_INFINITE // token(len(core) + 1:)
            end select
            out = out // token
            i = j + 1
        end do
    end function listing_safe_text

    !> `text` without leading/trailing blanks and with runs of blanks reduced to one (the
    !> compact echo of a listing line in the .mess).
    pure function compact_text(text) result(out)
        character(len=*), intent(in) :: text
        character(len=:), allocatable :: out
        integer :: i
        out = ''
        do i = 1, len_trim(text)
            if (text(i:i) == ' ') then
                if (len(out) == 0) cycle
                if (out(len(out):) == ' ') cycle
            end if
            out = out // text(i:i)
        end do
    end function compact_text

end module test_resu_checks
