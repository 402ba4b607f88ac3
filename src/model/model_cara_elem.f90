!> Element characteristics (AFFE_CARA_ELEM): COQUE, DISCRET / DISCRET_2D, ORIENTATION,
!> stored per cell. RIGI_PARASOL (model_rigi_parasol) fills the DISCRET data of springs.
module model_cara_elem
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text, to_upper
    use mesh_types, only: mesh_t, cell_label, CELL_POI1, CELL_SEG2
    use model_types, only: model_t, is_plate, is_discrete, is_discrete_2d, ELEMENT_NAMES
    implicit none
    private

    !> Code_Aster default of COQUE/COEF_RIGI_DRZ (fictitious drilling stiffness ratio).
    real(dp), parameter, public :: DEFAULT_COEF_RIGI_DRZ = 1.0e-5_dp

    !> Discrete characteristics (CARA of DISCRET): K = stiffness, T = translations,
    !> TR = translations + rotations, D = diagonal, N = on a node (POI1), L = on a link (SEG2).
    integer(i4), parameter, public :: CARA_NONE = 0, CARA_K_T_D_N = 1, CARA_K_T_D_L = 2, &
        CARA_K_TR_D_N = 3, CARA_K_TR_D_L = 4
    character(len=8), parameter, public :: CARA_NAMES(4) = ['K_T_D_N ', 'K_T_D_L ', &
        'K_TR_D_N', 'K_TR_D_L']
    integer(i4), parameter, public :: REPERE_GLOBAL = 1, REPERE_LOCAL = 2
    integer(i4), parameter, public :: ORIENT_NONE = 0, ORIENT_ANGL_VRIL = 1, &
        ORIENT_VECT_Y = 2, ORIENT_ANGL_NAUT = 3
    character(len=9), parameter, public :: ORIENT_NAMES(3) = ['ANGL_VRIL', 'VECT_Y   ', &
        'ANGL_NAUT']

    !> Characteristics per cell of the mesh.
    type, public :: cara_elem_t
        logical, allocatable :: has_coque(:)
        real(dp), allocatable :: thickness(:)          !< COQUE/EPAIS
        real(dp), allocatable :: coef_rigi_drz(:)      !< COQUE/COEF_RIGI_DRZ
        !> COQUE/ANGL_REP or VECTEUR: the direction whose projection on a plate cell is the
        !> x axis of its user frame (results are given in it); global X by default
        real(dp), allocatable :: coque_direction(:, :) !< (3, n_cells)
        integer(i4), allocatable :: coque_layers(:)    !< COQUE/COQUE_NCOU (default 1)
        integer(i4), allocatable :: discrete_cara(:)   !< CARA_* per cell
        integer(i4), allocatable :: discrete_repere(:) !< REPERE_GLOBAL / REPERE_LOCAL
        real(dp), allocatable :: discrete_values(:, :) !< (6, n_cells); first n used
        integer(i4), allocatable :: orientation(:)     !< ORIENT_* per cell
        real(dp), allocatable :: orientation_values(:, :)  !< (3, n_cells)
    end type cara_elem_t

    public :: cara_elem_init, assign_coque, assign_discrete, assign_orientation, &
        discrete_value_count, discrete_misfit, parse_cara, parse_repere

contains

    !> Empty characteristics for the cells of `mesh`.
    subroutine cara_elem_init(cara, mesh)
        type(cara_elem_t), intent(out) :: cara
        type(mesh_t), intent(in) :: mesh
        integer(i4) :: n
        n = mesh%n_cells
        allocate (cara%has_coque(n), source=.false.)
        allocate (cara%thickness(n), cara%coef_rigi_drz(n), source=0.0_dp)
        allocate (cara%coque_direction(3, n), source=0.0_dp)
        cara%coque_direction(1, :) = 1.0_dp
        allocate (cara%coque_layers(n), source=1_i4)
        allocate (cara%discrete_cara(n), source=CARA_NONE)
        allocate (cara%discrete_repere(n), source=REPERE_GLOBAL)
        allocate (cara%discrete_values(6, n), source=0.0_dp)
        allocate (cara%orientation(n), source=ORIENT_NONE)
        allocate (cara%orientation_values(3, n), source=0.0_dp)
    end subroutine cara_elem_init

    !> COQUE: thickness (and drilling coefficient) of plate cells.
    !>  cells : in, cells of the occurrence; each must carry a DKT/DKQ element
    !>  epais : in, thickness > 0;  coef_rigi_drz : in, optional (default 1e-5)
    !>  st    : out, STATUS_MODEL_ERROR for EPAIS <= 0 or a cell that is not a plate
    !>  direction : in, optional, ANGL_REP / VECTEUR as a direction (default global X)
    !>  layers : in, optional, COQUE_NCOU (default 1)
    subroutine assign_coque(cara, model, mesh, cells, epais, st, coef_rigi_drz, group, &
                            direction, layers)
        type(cara_elem_t), intent(inout) :: cara
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        real(dp), intent(in) :: epais
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: coef_rigi_drz
        character(len=*), intent(in), optional :: group
        real(dp), intent(in), optional :: direction(3)
        integer(i4), intent(in), optional :: layers
        integer(i4) :: i
        if (epais <= 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'EPAIS must be > 0, got ' // to_text(epais))
            return
        end if
        do i = 1, size(cells)
            if (.not. is_plate(model%element(cells(i)))) then
                call set_error(st, STATUS_MODEL_ERROR, 'COQUE on ' // &
                    cell_label(mesh, cells(i), group) // ', which is ' // &
                    trim(ELEMENT_NAMES(model%element(cells(i)))) // ' (COQUE needs DKT)')
                return
            end if
        end do
        cara%has_coque(cells) = .true.
        cara%thickness(cells) = epais
        cara%coef_rigi_drz(cells) = DEFAULT_COEF_RIGI_DRZ
        if (present(coef_rigi_drz)) cara%coef_rigi_drz(cells) = coef_rigi_drz
        do i = 1, size(cells)
            cara%coque_direction(:, cells(i)) = [1.0_dp, 0.0_dp, 0.0_dp]
            if (present(direction)) cara%coque_direction(:, cells(i)) = direction
        end do
        cara%coque_layers(cells) = 1
        if (present(layers)) cara%coque_layers(cells) = layers
    end subroutine assign_coque

    !> CARA code of a name (CARA_NONE if unknown), case-insensitive.
    pure integer(i4) function parse_cara(name) result(code)
        character(len=*), intent(in) :: name
        integer(i4) :: k
        code = CARA_NONE
        do k = 1, size(CARA_NAMES)
            if (to_upper(trim(name)) == trim(CARA_NAMES(k))) code = k
        end do
    end function parse_cara

    !> REPERE code of 'GLOBAL' / 'LOCAL', 0 otherwise.
    pure integer(i4) function parse_repere(name) result(code)
        character(len=*), intent(in) :: name
        code = 0
        if (to_upper(trim(name)) == 'GLOBAL') code = REPERE_GLOBAL
        if (to_upper(trim(name)) == 'LOCAL') code = REPERE_LOCAL
    end function parse_repere

    !> Number of values of CARA `code` for a 3D (DIS_*) or 2D (2D_DIS_*) discrete, as in
    !> Code_Aster: K_T_D_*: 3 / 2, K_TR_D_*: 6 / 3.
    pure integer(i4) function discrete_value_count(code, two_d) result(n)
        integer(i4), intent(in) :: code
        logical, intent(in) :: two_d
        select case (code)
        case (CARA_K_T_D_N, CARA_K_T_D_L)
            n = merge(2, 3, two_d)
        case (CARA_K_TR_D_N, CARA_K_TR_D_L)
            n = merge(3, 6, two_d)
        case default
            n = 0
        end select
    end function discrete_value_count

    !> Checks that CARA `code` fits cell c (modelisation and cell type); '' if it does,
    !> else the reason. Shared with RIGI_PARASOL.
    function discrete_misfit(model, mesh, c, code, keyword, group) result(reason)
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c, code
        character(len=*), intent(in) :: keyword
        character(len=*), intent(in), optional :: group
        character(len=:), allocatable :: reason
        character(len=:), allocatable :: cara_name
        reason = ''
        cara_name = trim(CARA_NAMES(code))
        if (.not. is_discrete(model%element(c))) then
            reason = cara_name // ' on ' // cell_label(mesh, c, group) // ', which is ' // &
                trim(ELEMENT_NAMES(model%element(c))) // ' (needs DIS_T or 2D_DIS_T)'
        else if (code == CARA_K_TR_D_N .or. code == CARA_K_TR_D_L) then
            reason = cara_name // ' on ' // cell_label(mesh, c, group) // ' needs the ' // &
                'DIS_TR modelisation, which parasol does not have (use K_T_D_N / K_T_D_L)'
        else if (is_discrete_2d(model%element(c)) .neqv. keyword == 'DISCRET_2D') then
            if (keyword /= 'RIGI_PARASOL') reason = keyword // ' on ' // &
                cell_label(mesh, c, group) // ', which is ' // &
                trim(ELEMENT_NAMES(model%element(c))) // ' (use ' // &
                trim(merge('DISCRET_2D', 'DISCRET   ', is_discrete_2d(model%element(c)))) // ')'
        end if
        if (len(reason) > 0) return
        if ((code == CARA_K_T_D_N) .neqv. (mesh%cell_type(c) == CELL_POI1)) then
            reason = cara_name // ' does not fit ' // cell_label(mesh, c, group) // ': ' // &
                trim(merge('K_T_D_N is for POI1 cells, K_T_D_L for SEG2', &
                           'K_T_D_L is for SEG2 cells, K_T_D_N for POI1', &
                           code == CARA_K_T_D_N))
        end if
        if (mesh%cell_type(c) /= CELL_POI1 .and. mesh%cell_type(c) /= CELL_SEG2) &
            reason = cara_name // ' on ' // cell_label(mesh, c, group) // ': not a discrete cell'
    end function discrete_misfit

    !> DISCRET / DISCRET_2D: stiffness values of discrete cells.
    !>  keyword : in, 'DISCRET' (DIS_T cells) or 'DISCRET_2D' (2D_DIS_T cells)
    !>  cara_name : in, K_T_D_N | K_T_D_L | K_TR_D_N | K_TR_D_L
    !>  values  : in, as many as discrete_value_count;  repere : in, 'GLOBAL' | 'LOCAL'
    !>  st      : out, STATUS_MODEL_ERROR for an unknown CARA or REPERE, a wrong value count,
    !>            a CARA that does not fit the cell type or modelisation (naming the cell)
    subroutine assign_discrete(cara, model, mesh, cells, keyword, cara_name, values, &
                               repere, st, group)
        type(cara_elem_t), intent(inout) :: cara
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        character(len=*), intent(in) :: keyword, cara_name, repere
        real(dp), intent(in) :: values(:)
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: group
        integer(i4) :: code, rep, i, c, n
        character(len=:), allocatable :: reason
        code = parse_cara(cara_name)
        rep = parse_repere(repere)
        if (code == CARA_NONE .or. rep == 0) then
            call set_error(st, STATUS_MODEL_ERROR, merge('CARA   ', 'REPERE ', code == &
                CARA_NONE) // trim(merge(cara_name, repere, code == CARA_NONE)) // &
                ' is not supported (CARA: K_T_D_N, K_T_D_L, K_TR_D_N, K_TR_D_L; ' // &
                'REPERE: GLOBAL, LOCAL)')
            return
        end if
        n = discrete_value_count(code, keyword == 'DISCRET_2D')
        if (size(values) /= n) then
            call set_error(st, STATUS_MODEL_ERROR, keyword // ' ' // trim(CARA_NAMES(code)) &
                // ' needs ' // to_text(n) // ' values in VALE, got ' // &
                to_text(size(values, kind=i4)))
            return
        end if
        do i = 1, size(cells)
            c = cells(i)
            reason = discrete_misfit(model, mesh, c, code, keyword, group)
            if (len(reason) > 0) then
                call set_error(st, STATUS_MODEL_ERROR, reason)
                return
            end if
            cara%discrete_cara(c) = code
            cara%discrete_repere(c) = rep
            cara%discrete_values(:, c) = 0.0_dp
            cara%discrete_values(1:n, c) = values
        end do
    end subroutine assign_discrete

    !> ORIENTATION: local frame data of discrete cells, stored as given.
    !>  kind_name : in, ANGL_VRIL (1 value, degrees), VECT_Y (3), ANGL_NAUT (3, degrees)
    !>  st : out, STATUS_MODEL_ERROR for an unknown CARA, a wrong value count or a cell that
    !>       is not a discrete
    subroutine assign_orientation(cara, model, mesh, cells, kind_name, values, st, group)
        type(cara_elem_t), intent(inout) :: cara
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        character(len=*), intent(in) :: kind_name
        real(dp), intent(in) :: values(:)
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: group
        integer(i4) :: code, k, n, i
        code = ORIENT_NONE
        do k = 1, size(ORIENT_NAMES)
            if (to_upper(trim(kind_name)) == trim(ORIENT_NAMES(k))) code = k
        end do
        if (code == ORIENT_NONE) then
            call set_error(st, STATUS_MODEL_ERROR, 'ORIENTATION CARA ' // kind_name // &
                           ' is not supported (ANGL_VRIL, VECT_Y, ANGL_NAUT)')
            return
        end if
        n = merge(1, 3, code == ORIENT_ANGL_VRIL)
        if (size(values) /= n) then
            call set_error(st, STATUS_MODEL_ERROR, 'ORIENTATION ' // trim(ORIENT_NAMES(code)) &
                // ' needs ' // to_text(n) // ' values in VALE, got ' // &
                to_text(size(values, kind=i4)))
            return
        end if
        do i = 1, size(cells)
            if (.not. is_discrete(model%element(cells(i)))) then
                call set_error(st, STATUS_MODEL_ERROR, 'ORIENTATION on ' // &
                    cell_label(mesh, cells(i), group) // ', which is not a discrete (' // &
                    trim(ELEMENT_NAMES(model%element(cells(i)))) // ')')
                return
            end if
            cara%orientation(cells(i)) = code
            cara%orientation_values(:, cells(i)) = 0.0_dp
            cara%orientation_values(1:n, cells(i)) = values
        end do
    end subroutine assign_orientation

end module model_cara_elem
