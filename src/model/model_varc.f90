!> Command variables (AFFE_MATERIAU AFFE_VARC, U4.43.03): the temperature (TEMP), the
!> hydration (HYDR) and the drying (SECH) fields each cell sees, and their reference
!> VALE_REF (TEMP, SECH), for the command-variable strains of the elements.
!>
!> Each AFFE_VARC occurrence is a source: NOM_VARC (parasol builds TEMP, HYDR, SECH),
!> VALE_REF, and the variable as one field (CHAM_GD) or as the fields of a result per instant
!> (EVOL, with Code_Aster's PROL_GAUCHE / PROL_DROITE = 'EXCLU' by default and FONC_INST,
!> the instant read as a function of the analysis' instant). The fields are copied when
!> AFFE_MATERIAU runs. A later occurrence replaces an earlier one on the cells they share.
!>
!> What a cell sees (cell_temperature_t), at each of its nodes:
!>  - TEMP of a NOEU field: one value, uniform through a plate's thickness;
!>  - TEMP_INF, TEMP_MIL, TEMP_SUP of a NOEU field: the plate's faces and mid-surface;
!>  - a CART or ELEM field: its values on the cell, the same at every node (a CART's
!>    TEMP_INF/MIL/SUP too);
!>  - the TEMP of an ELEM field with sub-points (CREA_RESU PREP_VARC: 3 per layer, INF,
!>    MOY, SUP, layer by layer from the bottom face), the same at every node.
!> In time, an EVOL is interpolated linearly between its two stored instants around the
!> instant (Code_Aster's rsinch).
!>
!> HYDR and SECH are scalars at the nodes of a cell (varc_cell_scalar): HYDR the component
!> HYDR of a HYDR_R field (NOEU, or ELNO as CREA_RESU's HYDR_ELNO; Code_Aster's default
!> NOM_CHAM for HYDR is HYDR_ELNO), SECH the component SECH of a TEMP_R field, or its TEMP
!> when it has no SECH (the drying computed by a thermal solver is stored as TEMP); a CART
!> or ELEM field gives its value on the cell to every node.
module model_varc
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text, real_e13
    use number_limits, only: MAX_TEMPERATURE
    use function_concept, only: function_concept_t, param_binding_t
    use mesh_types, only: mesh_t, cell_label, node_name
    use field_types, only: field_t, FIELD_NOEU, FIELD_CART, FIELD_ELEM, FIELD_ELNO, &
        field_component, &
        field_position, field_location_name
    implicit none
    private

    !> What a cell's temperature is (cell_temperature_t%kind).
    integer(i4), parameter, public :: TEMP_NONE = 0, TEMP_UNIFORM = 1, TEMP_PROFILE = 2, &
        TEMP_SUBPOINTS = 3

    !> The command variables parasol builds (varc_source_t%variable), by NOM_VARC.
    integer(i4), parameter, public :: VARC_TEMP = 1, VARC_HYDR = 2, VARC_SECH = 3, &
        VARC_COUNT = 3
    character(len=4), parameter, public :: VARC_NAMES(VARC_COUNT) = ['TEMP', 'HYDR', 'SECH']

    !> One AFFE_VARC occurrence.
    type, public :: varc_source_t
        character(len=:), allocatable :: label      !< for messages: "AFFE_VARC TEMP (EVOL T)"
        integer(i4) :: variable = VARC_TEMP         !< VARC_TEMP, VARC_HYDR or VARC_SECH
        real(dp) :: vale_ref = 0.0_dp
        logical :: evol = .false.
        integer(i4) :: n = 0                        !< instants (1 for CHAM_GD)
        real(dp), allocatable :: inst(:)            !< (n) instants of an EVOL, increasing
        type(field_t), allocatable :: fields(:)     !< (n) the variable's field at each
        character(len=8) :: prol_gauche = 'EXCLU', prol_droite = 'EXCLU'
        class(function_concept_t), pointer :: fonc_inst => null()
    end type varc_source_t

    !> The command variables of a material field: its sources and which one each cell sees.
    type, public :: varc_field_t
        integer(i4) :: n = 0
        type(varc_source_t), allocatable :: sources(:)
        integer(i4), allocatable :: cell_source(:, :) !< (VARC_COUNT, n_cells) 0: none
    end type varc_field_t

    !> The temperature of one cell at one instant (module header).
    type, public :: cell_temperature_t
        integer(i4) :: kind = TEMP_NONE
        integer(i4) :: nn = 0                       !< the cell's nodes
        integer(i4) :: n_sub = 0                    !< values per node (1, 3 or 3 x layers)
        real(dp) :: vale_ref = 0.0_dp
        real(dp), allocatable :: t(:, :)            !< (n_sub, nn)
    end type cell_temperature_t

    public :: varc_init, varc_add_source, varc_cell_temperature, varc_has_any, &
        field_cell_temperature, varc_cell_scalar, varc_cell_has

contains

    !> No command variable on the n_cells cells.
    subroutine varc_init(varc, n_cells)
        type(varc_field_t), intent(out) :: varc
        integer(i4), intent(in) :: n_cells
        allocate (varc%sources(0), varc%cell_source(VARC_COUNT, n_cells))
        varc%cell_source = 0
    end subroutine varc_init

    !> True when some cell sees a command variable.
    pure logical function varc_has_any(varc)
        type(varc_field_t), intent(in) :: varc
        varc_has_any = .false.
        if (allocated(varc%cell_source)) varc_has_any = any(varc%cell_source > 0)
    end function varc_has_any

    !> True when cell c sees command variable `variable` (VARC_TEMP, ...); any of them when
    !> `variable` is absent.
    pure logical function varc_cell_has(varc, c, variable)
        type(varc_field_t), intent(in) :: varc
        integer(i4), intent(in) :: c
        integer(i4), intent(in), optional :: variable
        varc_cell_has = .false.
        if (.not. allocated(varc%cell_source)) return
        if (c < 1 .or. c > size(varc%cell_source, 2)) return
        if (present(variable)) then
            varc_cell_has = varc%cell_source(variable, c) > 0
        else
            varc_cell_has = any(varc%cell_source(:, c) > 0)
        end if
    end function varc_cell_has

    !> Adds a source and gives it to `cells` (replacing an earlier one there).
    subroutine varc_add_source(varc, source, cells)
        type(varc_field_t), intent(inout) :: varc
        type(varc_source_t), intent(in) :: source
        integer(i4), intent(in) :: cells(:)
        type(varc_source_t), allocatable :: bigger(:)
        allocate (bigger(varc%n + 1))
        bigger(1:varc%n) = varc%sources(1:varc%n)
        bigger(varc%n + 1) = source
        call move_alloc(bigger, varc%sources)
        varc%n = varc%n + 1
        varc%cell_source(source%variable, cells) = varc%n
    end subroutine varc_add_source

    !> The temperature cell c sees at instant t (kind TEMP_NONE when it sees none).
    !>  st : out, STATUS_MODEL_ERROR for an instant outside an EVOL's instants with
    !>       PROL_*='EXCLU', FONC_INST failing, a node or cell without the temperature
    !>       component, or a field of another kind; naming the cell and the source
    subroutine varc_cell_temperature(varc, mesh, c, t, temp, st)
        type(varc_field_t), intent(in) :: varc
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: t
        type(cell_temperature_t), intent(out) :: temp
        type(status_t), intent(out) :: st
        type(cell_temperature_t) :: second
        integer(i4) :: s, i1, i2
        real(dp) :: w
        s = 0
        if (varc_cell_has(varc, c, VARC_TEMP)) s = varc%cell_source(VARC_TEMP, c)
        if (s == 0) return
        associate (src => varc%sources(s))
            call instants_around(src, t, i1, i2, w, st)
            if (st%ok()) call field_cell_temperature(src%fields(i1), mesh, c, temp, st)
            if (st%ok()) call check_bounded(temp, st)
            if (st%ok() .and. i2 /= i1) then
                call field_cell_temperature(src%fields(i2), mesh, c, second, st)
                if (st%ok()) call check_bounded(second, st)
                if (st%ok()) then
                    if (second%kind /= temp%kind .or. second%n_sub /= temp%n_sub) then
                        call set_error(st, STATUS_MODEL_ERROR, 'the TEMP fields at INST ' // &
                            real_e13(src%inst(i1)) // ' and ' // real_e13(src%inst(i2)) // &
                            ' are not of the same kind on the cell')
                    else
                        temp%t = (1.0_dp - w) * temp%t + w * second%t
                    end if
                end if
            end if
            temp%vale_ref = src%vale_ref
            if (st%failed()) call set_error(st, st%code, src%label // ' on ' // &
                cell_label(mesh, c) // ': ' // st%message)
        end associate
    end subroutine varc_cell_temperature

    !> The value of command variable `variable` (VARC_HYDR or VARC_SECH) at the nodes of cell
    !> c at instant t, interpolated in time as the temperature; has = .false. when the cell
    !> does not see it.
    !>  values   : out, (nn) at the cell's nodes
    !>  vale_ref : out, the source's VALE_REF (SECH's reference drying)
    !>  st : out, STATUS_MODEL_ERROR for an instant outside an EVOL, a node or cell without
    !>       the component, a value beyond MAX_TEMPERATURE; naming the cell and the source
    subroutine varc_cell_scalar(varc, mesh, c, variable, t, values, vale_ref, has, st)
        type(varc_field_t), intent(in) :: varc
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c, variable
        real(dp), intent(in) :: t
        real(dp), allocatable, intent(out) :: values(:)
        real(dp), intent(out) :: vale_ref
        logical, intent(out) :: has
        type(status_t), intent(out) :: st
        real(dp), allocatable :: second(:)
        integer(i4) :: s, i1, i2
        real(dp) :: w
        has = .false.
        vale_ref = 0.0_dp
        if (.not. varc_cell_has(varc, c, variable)) return
        s = varc%cell_source(variable, c)
        associate (src => varc%sources(s))
            call instants_around(src, t, i1, i2, w, st)
            if (st%ok()) call field_cell_scalar(src%fields(i1), mesh, c, variable, values, st)
            if (st%ok() .and. i2 /= i1) then
                call field_cell_scalar(src%fields(i2), mesh, c, variable, second, st)
                if (st%ok()) values = (1.0_dp - w) * values + w * second
            end if
            if (st%ok()) then
                if (.not. all(abs(values) <= MAX_TEMPERATURE)) call set_error(st, &
                    STATUS_MODEL_ERROR, 'the field has ' // real_e13(maxval(abs(values))) // &
                    ' on the cell, beyond the values parasol takes for a command variable ' // &
                    '(|' // VARC_NAMES(variable) // '| <= ' // real_e13(MAX_TEMPERATURE) // ')')
            end if
            vale_ref = src%vale_ref
            has = st%ok()
            if (st%failed()) call set_error(st, st%code, src%label // ' on ' // &
                cell_label(mesh, c) // ': ' // st%message)
        end associate
    end subroutine varc_cell_scalar

    ! The scalar command variable (HYDR, SECH) of field f at the nodes of cell c (module
    ! header: its component, and the locations read).
    subroutine field_cell_scalar(f, mesh, c, variable, values, st)
        type(field_t), intent(in) :: f
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c, variable
        real(dp), allocatable, intent(out) :: values(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: nodes(:)
        integer(i4) :: k, nn, i
        integer(i8) :: pos
        character(len=:), allocatable :: wanted
        nodes = mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)
        nn = size(nodes, kind=i4)
        allocate (values(nn), source=0.0_dp)
        wanted = VARC_NAMES(variable)
        k = field_component(f, wanted)
        if (k == 0 .and. variable == VARC_SECH) then
            wanted = 'TEMP'
            k = field_component(f, wanted)
        end if
        if (k == 0) then
            call set_error(st, STATUS_MODEL_ERROR, 'the field has no component ' // &
                VARC_NAMES(variable) // merge(' (nor TEMP)', '           ', &
                variable == VARC_SECH))
            st%message = trim(st%message)
            return
        end if
        select case (f%location)
        case (FIELD_NOEU)
            do i = 1, nn
                if (.not. f%node_has(k, nodes(i))) then
                    call set_error(st, STATUS_MODEL_ERROR, 'the field has no ' // wanted // &
                        ' at node ' // node_name(mesh, nodes(i)))
                    return
                end if
                values(i) = f%node_values(k, nodes(i))
            end do
        case (FIELD_ELNO, FIELD_CART, FIELD_ELEM)
            do i = 1, nn
                pos = 0
                if (f%location == FIELD_ELNO) then
                    pos = field_position(f, c, i, 1_i4, k)
                else
                    pos = field_position(f, c, 1_i4, 1_i4, k)
                end if
                if (pos == 0) then
                    call set_error(st, STATUS_MODEL_ERROR, 'the field has no ' // wanted // &
                        ' on the cell')
                    return
                end if
                values(i) = f%values(pos)
            end do
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'a field ' // field_location_name(f) // &
                ' is not read by AFFE_VARC ' // VARC_NAMES(variable) // ' (NOEU, ELNO, ' // &
                'CART or ELEM)')
        end select
    end subroutine field_cell_scalar

    ! The temperatures a cell sees are bounded (number_limits MAX_TEMPERATURE) before the
    ! elements interpolate them and form strains and stresses from them.
    subroutine check_bounded(temp, st)
        type(cell_temperature_t), intent(in) :: temp
        type(status_t), intent(inout) :: st
        if (.not. allocated(temp%t)) return
        if (all(abs(temp%t) <= MAX_TEMPERATURE)) return
        call set_error(st, STATUS_MODEL_ERROR, 'the temperature field has ' // &
            real_e13(maxval(abs(temp%t))) // ' on the cell, beyond the temperatures ' // &
            'parasol takes (|T| <= ' // real_e13(MAX_TEMPERATURE) // ')')
    end subroutine check_bounded

    ! The stored instants i1 <= i2 around the instant read at t, and the weight of i2.
    subroutine instants_around(src, t, i1, i2, w, st)
        type(varc_source_t), intent(in) :: src
        real(dp), intent(in) :: t
        integer(i4), intent(out) :: i1, i2
        real(dp), intent(out) :: w
        type(status_t), intent(out) :: st
        type(param_binding_t) :: binding
        real(dp) :: tr, tol
        integer(i4) :: k
        i1 = 1
        i2 = 1
        w = 0.0_dp
        if (.not. src%evol .or. src%n == 1) return
        tr = t
        if (associated(src%fonc_inst)) then
            call src%fonc_inst%bind(['INST'], binding)
            call src%fonc_inst%evaluate(binding, [t], tr, st)
            if (st%failed()) then
                call set_error(st, st%code, 'FONC_INST: ' // st%message)
                return
            end if
        end if
        tol = 1.0e-6_dp * max(abs(src%inst(1)), abs(src%inst(src%n)), tiny(1.0_dp))
        if (tr < src%inst(1) - tol) then
            call outside(src%prol_gauche, 1_i4, 2_i4, 'PROL_GAUCHE')
        else if (tr > src%inst(src%n) + tol) then
            call outside(src%prol_droite, src%n - 1, src%n, 'PROL_DROITE')
        else
            do k = 1, src%n
                if (abs(tr - src%inst(k)) <= tol) then
                    i1 = k
                    i2 = k
                    return
                end if
            end do
            do k = 1, src%n - 1
                if (tr < src%inst(k + 1)) exit
            end do
            i1 = k
            i2 = k + 1
            w = (tr - src%inst(k)) / (src%inst(k + 1) - src%inst(k))
        end if
    contains
        subroutine outside(prol, a, b, key)
            character(len=*), intent(in) :: prol, key
            integer(i4), intent(in) :: a, b
            select case (trim(prol))
            case ('CONSTANT')
                i1 = merge(1_i4, src%n, key == 'PROL_GAUCHE')
                i2 = i1
            case ('LINEAIRE')
                i1 = a
                i2 = b
                w = (tr - src%inst(a)) / (src%inst(b) - src%inst(a))
            case default
                call set_error(st, STATUS_MODEL_ERROR, 'INST ' // real_e13(tr) // &
                    ' is outside the instants of the EVOL (' // real_e13(src%inst(1)) // &
                    ' to ' // real_e13(src%inst(src%n)) // ') and ' // key // '=''EXCLU''')
            end select
        end subroutine outside
    end subroutine instants_around

    !> The temperature of cell c in one TEMP field (module header; CREA_RESU PREP_VARC
    !> reads its input so too).
    !>  st : out, the component missing at a node or on the cell, a field of another kind
    subroutine field_cell_temperature(f, mesh, c, temp, st)
        type(field_t), intent(in) :: f
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        type(cell_temperature_t), intent(out) :: temp
        type(status_t), intent(out) :: st
        integer(i4) :: k_temp, k_prof(3), nn, i, node, j
        integer(i4), allocatable :: nodes(:)
        nodes = mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c + 1) - 1)
        nn = size(nodes, kind=i4)
        temp%nn = nn
        k_temp = field_component(f, 'TEMP')
        k_prof = [field_component(f, 'TEMP_INF'), field_component(f, 'TEMP_MIL'), &
                  field_component(f, 'TEMP_SUP')]
        select case (f%location)
        case (FIELD_NOEU)
            if (k_temp > 0) then
                if (all(f%node_has(k_temp, nodes))) then
                    call set_kind(TEMP_UNIFORM, 1_i4)
                    temp%t(1, :) = f%node_values(k_temp, nodes)
                    return
                end if
            end if
            if (all(k_prof > 0)) then
                if (all(f%node_has(k_prof, nodes(1:1)))) then
                    call set_kind(TEMP_PROFILE, 3_i4)
                    do i = 1, nn
                        node = nodes(i)
                        if (.not. all(f%node_has(k_prof, node))) then
                            call set_error(st, STATUS_MODEL_ERROR, 'node ' // &
                                node_name(mesh, node) // ' has no TEMP_INF, TEMP_MIL, TEMP_SUP')
                            return
                        end if
                        temp%t(:, i) = f%node_values(k_prof, node)
                    end do
                    return
                end if
            end if
            do i = 1, nn
                if (k_temp == 0) exit
                if (.not. f%node_has(k_temp, nodes(i))) exit
            end do
            call set_error(st, STATUS_MODEL_ERROR, 'the temperature field has no TEMP (nor ' &
                // 'TEMP_INF, TEMP_MIL, TEMP_SUP) at node ' // node_name(mesh, nodes(min(i, nn))))
        case (FIELD_CART, FIELD_ELEM)
            if (c > f%n_cells) then
                call missing()
            else if (f%n_points(c) == 0) then
                call missing()
            else if (k_temp > 0 .and. field_position(f, c, 1_i4, 1_i4, k_temp) > 0) then
                if (f%n_subpoints(c) == 1) then
                    call set_kind(TEMP_UNIFORM, 1_i4)
                else
                    call set_kind(TEMP_SUBPOINTS, f%n_subpoints(c))
                end if
                do j = 1, temp%n_sub
                    temp%t(j, :) = f%values(field_position(f, c, 1_i4, j, k_temp))
                end do
            else if (all(k_prof > 0)) then
                if (any([(field_position(f, c, 1_i4, 1_i4, k_prof(j)) == 0, j = 1, 3)])) then
                    call missing()
                    return
                end if
                call set_kind(TEMP_PROFILE, 3_i4)
                do j = 1, 3
                    temp%t(j, :) = f%values(field_position(f, c, 1_i4, 1_i4, k_prof(j)))
                end do
            else
                call missing()
            end if
        case default
            call set_error(st, STATUS_MODEL_ERROR, 'a temperature field ' // &
                field_location_name(f) // ' is not read by AFFE_VARC here (NOEU, CART or ' &
                // 'ELEM)')
        end select
    contains
        subroutine set_kind(kind, n_sub)
            integer(i4), intent(in) :: kind, n_sub
            temp%kind = kind
            temp%n_sub = n_sub
            allocate (temp%t(n_sub, nn))
        end subroutine set_kind
        subroutine missing()
            call set_error(st, STATUS_MODEL_ERROR, 'the temperature field has no TEMP (nor ' &
                // 'TEMP_INF, TEMP_MIL, TEMP_SUP) on the cell')
        end subroutine missing
    end subroutine field_cell_temperature

end module model_varc
