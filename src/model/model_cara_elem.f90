!> Element characteristics (AFFE_CARA_ELEM): COQUE, DISCRET / DISCRET_2D, ORIENTATION,
!> stored per cell. RIGI_PARASOL (model_rigi_parasol) fills the DISCRET data of springs.
module model_cara_elem
    use kinds, only: dp, i4
    use status, only: status_t, set_error, STATUS_MODEL_ERROR
    use strings, only: to_text, to_upper
    use mesh_types, only: mesh_t, cell_label, CELL_POI1, CELL_SEG2
    use model_types, only: model_t, is_plate, is_discrete, is_discrete_2d, &
        is_discrete_rotational, ELEMENT_NAMES, is_plate_edge, ELEM_NONE, is_plane_solid
    implicit none
    private

    !> Code_Aster default of COQUE/COEF_RIGI_DRZ (fictitious drilling stiffness ratio).
    real(dp), parameter, public :: DEFAULT_COEF_RIGI_DRZ = 1.0e-5_dp

    !> Discrete stiffness characteristics (CARA of DISCRET, U4.42.01): K = stiffness,
    !> T = translations, TR = translations + rotations, D = diagonal (else the full matrix),
    !> N = on a node (POI1), L = on a link (SEG2). The masses (M_*) and dampings (A_*) of the
    !> same names are accepted and checked against the cells, and play no part in statics.
    integer(i4), parameter, public :: CARA_NONE = 0, CARA_K_T_D_N = 1, CARA_K_T_D_L = 2, &
        CARA_K_TR_D_N = 3, CARA_K_TR_D_L = 4, CARA_K_T_N = 5, CARA_K_T_L = 6, &
        CARA_K_TR_N = 7, CARA_K_TR_L = 8
    character(len=8), parameter, public :: CARA_NAMES(8) = ['K_T_D_N ', 'K_T_D_L ', &
        'K_TR_D_N', 'K_TR_D_L', 'K_T_N   ', 'K_T_L   ', 'K_TR_N  ', 'K_TR_L  ']

    !> A full discrete matrix (K_T_N, K_T_L, K_TR_N, K_TR_L), in the frame of its REPERE.
    type, public :: discrete_matrix_t
        real(dp), allocatable :: k(:, :)
        !> .false.: K(i,j) /= K(j,i) somewhere (SYME='NON' with values that are not
        !> symmetric): the analyses factor its symmetric part and correct for the rest
        !> (unsymmetric_discretes)
        logical :: symmetric = .true.
    end type discrete_matrix_t
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
        real(dp), allocatable :: coque_offset(:)       !< COQUE/EXCENTREMENT (default 0)
        integer(i4), allocatable :: discrete_cara(:)   !< CARA_* per cell
        integer(i4), allocatable :: discrete_repere(:) !< REPERE_GLOBAL / REPERE_LOCAL
        real(dp), allocatable :: discrete_values(:, :) !< (6, n_cells); first n used
        integer(i4), allocatable :: orientation(:)     !< ORIENT_* per cell
        real(dp), allocatable :: orientation_values(:, :)  !< (3, n_cells)
        !> (n_cells) index in `matrices` of a cell's full matrix, 0 for a diagonal one
        integer(i4), allocatable :: discrete_matrix(:)
        type(discrete_matrix_t), allocatable :: matrices(:)   !< one per DISCRET occurrence
        integer(i4) :: n_matrices = 0
        !> (n_cells) a discrete mass (M_*) that is not zero: its values are not kept (they
        !> play no part in statics), PESANTEUR on it is refused
        logical, allocatable :: has_mass(:)
        !> MASSIF: the material frame of a plane solid cell, as given (MASSIF_* kind, 0
        !> none): ANGL_REP or ANGL_EULER (3 angles, degrees; in 2D the first turns about Z),
        !> or ANGL_AXE (2 angles) and ORIG_AXE (3 coordinates). Only an orthotropic
        !> material turns with it; an isotropic one is the same in every frame.
        integer(i4), allocatable :: massif_kind(:)
        real(dp), allocatable :: massif_values(:, :)   !< (5, n_cells)
    end type cara_elem_t

    integer(i4), parameter, public :: MASSIF_NONE = 0, MASSIF_ANGL_REP = 1, &
        MASSIF_ANGL_EULER = 2, MASSIF_AXE = 3

    public :: cara_elem_init, assign_coque, assign_discrete, assign_orientation, &
        material_axis_angle, assign_massif, discrete_value_count, discrete_misfit, parse_cara, parse_repere, cara_is_rotational, &
        cara_is_diagonal, cara_on_link, discrete_node_dofs, discrete_full_matrix, &
        discrete_is_unsymmetric

contains

    !> Empty characteristics for the cells of `mesh`.
    subroutine cara_elem_init(cara, mesh)
        type(cara_elem_t), intent(out) :: cara
        type(mesh_t), intent(in) :: mesh
        integer(i4) :: n
        n = mesh%n_cells
        allocate (cara%has_coque(n), source=.false.)
        allocate (cara%massif_kind(n), source=MASSIF_NONE)
        allocate (cara%massif_values(5, n), source=0.0_dp)
        allocate (cara%thickness(n), cara%coef_rigi_drz(n), source=0.0_dp)
        allocate (cara%coque_direction(3, n), source=0.0_dp)
        cara%coque_direction(1, :) = 1.0_dp
        allocate (cara%coque_layers(n), source=1_i4)
        allocate (cara%coque_offset(n), source=0.0_dp)
        allocate (cara%discrete_cara(n), source=CARA_NONE)
        allocate (cara%discrete_repere(n), source=REPERE_GLOBAL)
        allocate (cara%discrete_values(6, n), source=0.0_dp)
        allocate (cara%orientation(n), source=ORIENT_NONE)
        allocate (cara%orientation_values(3, n), source=0.0_dp)
        allocate (cara%discrete_matrix(n), source=0_i4)
        allocate (cara%matrices(4))
        allocate (cara%has_mass(n), source=.false.)
    end subroutine cara_elem_init

    !> COQUE: thickness (and drilling coefficient) of plate cells.
    !>  cells_in : in, cells of the occurrence; each must carry a DKT/DKQ element (or a
    !>             plate edge, or none: then passed over)
    !>  epais : in, thickness > 0;  coef_rigi_drz : in, optional (default 1e-5)
    !>  st    : out, STATUS_MODEL_ERROR for EPAIS <= 0 or a cell that is not a plate
    !>  direction : in, optional, ANGL_REP / VECTEUR as a direction (default global X)
    !>  layers : in, optional, COQUE_NCOU (default 1)
    !>  offset : in, optional, EXCENTREMENT (default 0)
    subroutine assign_coque(cara, model, mesh, cells_in, epais, st, coef_rigi_drz, group, &
                            direction, layers, offset)
        type(cara_elem_t), intent(inout) :: cara
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells_in(:)
        real(dp), intent(in) :: epais
        type(status_t), intent(out) :: st
        real(dp), intent(in), optional :: coef_rigi_drz
        character(len=*), intent(in), optional :: group
        real(dp), intent(in), optional :: direction(3)
        integer(i4), intent(in), optional :: layers
        real(dp), intent(in), optional :: offset
        integer(i4) :: i
        integer(i4), allocatable :: cells(:)
        if (epais <= 0.0_dp) then
            call set_error(st, STATUS_MODEL_ERROR, 'EPAIS must be > 0, got ' // to_text(epais))
            return
        end if
        ! a cell without an element is passed over (Code_Aster's map covers the mesh); the
        ! plates' edges (SEG2 of a DKT model) take it too, as Code_Aster's MEBODKT
        cells = pack(cells_in, model%element(cells_in) /= ELEM_NONE)
        do i = 1, size(cells)
            if (.not. (is_plate(model%element(cells(i))) .or. &
                       is_plate_edge(model%element(cells(i))))) then
                call set_error(st, STATUS_MODEL_ERROR, 'COQUE on ' // &
                    cell_label(mesh, cells(i), group) // ', which is ' // &
                    trim(ELEMENT_NAMES(model%element(cells(i)))) // ' (COQUE needs DKT)')
                return
            end if
        end do
        cara%has_coque(cells) = .true.
        cara%thickness(cells) = epais
        cara%coef_rigi_drz(cells) = DEFAULT_COEF_RIGI_DRZ
        cara%coque_offset(cells) = 0.0_dp
        if (present(offset)) cara%coque_offset(cells) = offset
        if (present(coef_rigi_drz)) cara%coef_rigi_drz(cells) = coef_rigi_drz
        do i = 1, size(cells)
            cara%coque_direction(:, cells(i)) = [1.0_dp, 0.0_dp, 0.0_dp]
            if (present(direction)) cara%coque_direction(:, cells(i)) = direction
        end do
        cara%coque_layers(cells) = 1
        if (present(layers)) cara%coque_layers(cells) = layers
    end subroutine assign_coque

    !> CARA code of a stiffness name (CARA_NONE if unknown), case-insensitive.
    pure integer(i4) function parse_cara(name) result(code)
        character(len=*), intent(in) :: name
        integer(i4) :: k
        code = CARA_NONE
        do k = 1, size(CARA_NAMES)
            if (to_upper(trim(name)) == trim(CARA_NAMES(k))) code = k
        end do
    end function parse_cara

    !> The shape of any discrete characteristic name K_*, M_*, A_* (module header):
    !>  what : out, 'K', 'M' or 'A' (' ' when the name is not one of Code_Aster's 24)
    !>  rotational, diagonal, on_link : out, TR, D, L
    pure subroutine parse_discrete_name(name, what, rotational, diagonal, on_link)
        character(len=*), intent(in) :: name
        character, intent(out) :: what
        logical, intent(out) :: rotational, diagonal, on_link
        character(len=:), allocatable :: n, rest
        n = to_upper(trim(name))
        what = ' '
        rotational = .false.
        diagonal = .false.
        on_link = .false.
        if (len(n) < 5) return
        if (index('KMA', n(1:1)) == 0 .or. n(2:2) /= '_') return
        rest = n(3:)
        if (rest(1:2) == 'TR') then
            rotational = .true.
            rest = rest(3:)
        else if (rest(1:1) == 'T') then
            rest = rest(2:)
        else
            return
        end if
        if (len(rest) >= 3) then
            if (rest(1:3) == '_D_') then
                diagonal = .true.
                rest = rest(3:)
            end if
        end if
        if (rest /= '_N' .and. rest /= '_L') return
        on_link = rest == '_L'
        what = n(1:1)
    end subroutine parse_discrete_name

    !> Properties of a stiffness code: TR, D, L.
    elemental logical function cara_is_rotational(code)
        integer(i4), intent(in) :: code
        cara_is_rotational = any(code == [CARA_K_TR_D_N, CARA_K_TR_D_L, CARA_K_TR_N, &
                                          CARA_K_TR_L])
    end function cara_is_rotational

    elemental logical function cara_is_diagonal(code)
        integer(i4), intent(in) :: code
        cara_is_diagonal = code >= CARA_K_T_D_N .and. code <= CARA_K_TR_D_L
    end function cara_is_diagonal

    elemental logical function cara_on_link(code)
        integer(i4), intent(in) :: code
        cara_on_link = any(code == [CARA_K_T_D_L, CARA_K_TR_D_L, CARA_K_T_L, CARA_K_TR_L])
    end function cara_on_link

    !> DOFs per node of a discrete: T 3 (2D: 2), TR 6 (2D: 3).
    elemental integer(i4) function discrete_node_dofs(rotational, two_d) result(n)
        logical, intent(in) :: rotational, two_d
        if (rotational) then
            n = merge(3, 6, two_d)
        else
            n = merge(2, 3, two_d)
        end if
    end function discrete_node_dofs

    !> REPERE code of 'GLOBAL' / 'LOCAL', 0 otherwise.
    pure integer(i4) function parse_repere(name) result(code)
        character(len=*), intent(in) :: name
        code = 0
        if (to_upper(trim(name)) == 'GLOBAL') code = REPERE_GLOBAL
        if (to_upper(trim(name)) == 'LOCAL') code = REPERE_LOCAL
    end function parse_repere

    !> Number of values of stiffness CARA `code` for a 3D (DIS_*) or 2D (2D_DIS_*)
    !> discrete, as Code_Aster's catalog: a diagonal one its DOFs per node; a full one the
    !> upper triangle (by column) of its matrix, or with symmetric = .false. (SYME='NON') the
    !> whole matrix (by column).
    pure integer(i4) function discrete_value_count(code, two_d, symmetric) result(n)
        integer(i4), intent(in) :: code
        logical, intent(in) :: two_d
        logical, intent(in), optional :: symmetric
        integer(i4) :: order
        logical :: sym
        n = 0
        if (code == CARA_NONE) return
        sym = .true.
        if (present(symmetric)) sym = symmetric
        n = discrete_node_dofs(cara_is_rotational(code), two_d)
        if (cara_is_diagonal(code)) return
        order = n * merge(2, 1, cara_on_link(code))
        n = merge(order * (order + 1) / 2, order * order, sym)
    end function discrete_value_count

    ! Number of values of a mass or damping name (M_T_D_N: the mass; M_TR_D_N: the mass,
    ! the inertia tensor, the offset; A_*: as K_*).
    pure integer(i4) function inertia_value_count(name, two_d, symmetric) result(n)
        character(len=*), intent(in) :: name
        logical, intent(in) :: two_d, symmetric
        character :: what
        logical :: rotational, diagonal, on_link
        integer(i4) :: code
        call parse_discrete_name(name, what, rotational, diagonal, on_link)
        code = parse_cara('K' // to_upper(trim(name(2:))))
        n = discrete_value_count(code, two_d, symmetric)
        if (what /= 'M' .or. .not. diagonal) return
        if (.not. rotational) then
            n = 1
        else if (on_link) then
            n = merge(2, 4, two_d)
        else
            n = merge(4, 10, two_d)
        end if
    end function inertia_value_count

    !> Whether cell c's stiffness is a full matrix that is not symmetric (SYME='NON').
    pure logical function discrete_is_unsymmetric(cara, c)
        type(cara_elem_t), intent(in) :: cara
        integer(i4), intent(in) :: c
        integer(i4) :: id
        discrete_is_unsymmetric = .false.
        if (.not. allocated(cara%discrete_matrix)) return
        if (c < 1 .or. c > size(cara%discrete_matrix)) return
        id = cara%discrete_matrix(c)
        if (id > 0) discrete_is_unsymmetric = .not. cara%matrices(id)%symmetric
    end function discrete_is_unsymmetric

    !> The full matrix of a full stiffness CARA from its VALE: the upper triangle by column
    !> (K11, K12, K22, K13, ... : Code_Aster's vecma), or with symmetric = .false. the whole
    !> matrix by column (SYME='NON', U4.42.01 §5: K(i,j) may differ from K(j,i)).
    pure subroutine discrete_full_matrix(values, order, symmetric, k)
        real(dp), intent(in) :: values(:)
        integer(i4), intent(in) :: order
        logical, intent(in) :: symmetric
        real(dp), allocatable, intent(out) :: k(:, :)
        integer(i4) :: i, j, p
        allocate (k(order, order), source=0.0_dp)
        p = 0
        do j = 1, order
            do i = 1, merge(j, order, symmetric)
                p = p + 1
                k(i, j) = values(p)
                if (symmetric) k(j, i) = values(p)
            end do
        end do
    end subroutine discrete_full_matrix

    !> Checks that a discrete characteristic fits cell c (modelisation and cell type);
    !> '' if it does, else the reason. Shared with RIGI_PARASOL.
    !>  code    : in, a stiffness code, or CARA_NONE with `name` for a mass or damping
    !>  keyword : in, DISCRET, DISCRET_2D or RIGI_PARASOL
    !>  name    : in, optional, the CARA as written (messages; masses and dampings)
    function discrete_misfit(model, mesh, c, code, keyword, group, name) result(reason)
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c, code
        character(len=*), intent(in) :: keyword
        character(len=*), intent(in), optional :: group, name
        character(len=:), allocatable :: reason
        character(len=:), allocatable :: cara_name
        character :: what
        logical :: rotational, diagonal, on_link
        integer(i4) :: kind
        reason = ''
        if (present(name)) then
            cara_name = to_upper(trim(name))
        else
            cara_name = trim(CARA_NAMES(code))
        end if
        call parse_discrete_name(cara_name, what, rotational, diagonal, on_link)
        kind = model%element(c)
        if (.not. is_discrete(kind)) then
            reason = cara_name // ' on ' // cell_label(mesh, c, group) // ', which is ' // &
                trim(ELEMENT_NAMES(kind)) // ' (needs DIS_T, 2D_DIS_T, DIS_TR or 2D_DIS_TR)'
        else if (rotational .neqv. is_discrete_rotational(kind)) then
            reason = cara_name // ' on ' // cell_label(mesh, c, group) // ', which is ' // &
                trim(ELEMENT_NAMES(kind)) // ' (' // trim(merge('K_TR_*, M_TR_*, A_TR_* ', &
                'K_T_*, M_T_*, A_T_*    ', rotational)) // ' go with ' // &
                trim(merge('DIS_TR or 2D_DIS_TR', 'DIS_T or 2D_DIS_T  ', rotational)) // ')'
        else if (is_discrete_2d(kind) .neqv. keyword == 'DISCRET_2D') then
            if (keyword /= 'RIGI_PARASOL') reason = keyword // ' on ' // &
                cell_label(mesh, c, group) // ', which is ' // trim(ELEMENT_NAMES(kind)) // &
                ' (use ' // trim(merge('DISCRET_2D', 'DISCRET   ', is_discrete_2d(kind))) // ')'
        end if
        if (len(reason) > 0) return
        if (on_link .eqv. (mesh%cell_type(c) == CELL_POI1)) then
            reason = cara_name // ' does not fit ' // cell_label(mesh, c, group) // ': ' // &
                trim(merge(cara_name // ' is for SEG2 cells, ' // partner() // ' for POI1', &
                           cara_name // ' is for POI1 cells, ' // partner() // ' for SEG2', &
                           on_link))
        end if
        if (mesh%cell_type(c) /= CELL_POI1 .and. mesh%cell_type(c) /= CELL_SEG2) &
            reason = cara_name // ' on ' // cell_label(mesh, c, group) // ': not a discrete cell'
    contains
        ! The same characteristic on the other cell type (K_T_D_L <-> K_T_D_N).
        function partner() result(other)
            character(len=:), allocatable :: other
            other = cara_name(1:len(cara_name) - 1) // merge('N', 'L', on_link)
        end function partner
    end function discrete_misfit

    !> DISCRET / DISCRET_2D: the characteristic of discrete cells. A stiffness (K_*) is
    !> stored (a later one replaces an earlier one on a cell); a mass or damping (M_*, A_*)
    !> is checked against the cells and otherwise accepted: it plays no part in statics.
    !>  keyword   : in, 'DISCRET' (3D discretes) or 'DISCRET_2D' (2D ones)
    !>  cara_name : in, one of Code_Aster's 24 (K_T_D_N ... A_TR_L)
    !>  values    : in, as many as the catalog says (discrete_value_count)
    !>  repere    : in, 'GLOBAL' | 'LOCAL'
    !>  st        : out, STATUS_MODEL_ERROR for an unknown CARA or REPERE, a wrong value
    !>              count, a characteristic that does not fit a cell (naming it)
    !>  symmetric : in, optional, SYME='OUI' (default) or 'NON'
    !>  verify    : in, optional, VERIF='MAILLE' (default .true.): a cell of the groups that
    !>              carries no discrete element is an error; without it (Code_Aster's
    !>              default) such cells are passed over and counted in n_skipped
    !>  n_skipped : out, optional, the cells passed over
    subroutine assign_discrete(cara, model, mesh, cells, keyword, cara_name, values, &
                               repere, st, group, symmetric, verify, n_skipped)
        type(cara_elem_t), intent(inout) :: cara
        type(model_t), intent(in) :: model
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: cells(:)
        character(len=*), intent(in) :: keyword, cara_name, repere
        real(dp), intent(in) :: values(:)
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: group
        logical, intent(in), optional :: symmetric, verify
        integer(i4), intent(out), optional :: n_skipped
        integer(i4) :: code, rep, i, c, n, skipped, matrix
        logical :: sym, check_all, rotational, diagonal, on_link, two_d
        character :: what
        character(len=:), allocatable :: reason
        real(dp), allocatable :: k(:, :)
        sym = .true.
        if (present(symmetric)) sym = symmetric
        check_all = .true.
        if (present(verify)) check_all = verify
        skipped = 0
        if (present(n_skipped)) n_skipped = 0
        two_d = keyword == 'DISCRET_2D'
        call parse_discrete_name(cara_name, what, rotational, diagonal, on_link)
        code = parse_cara(cara_name)
        rep = parse_repere(repere)
        if (what == ' ' .or. rep == 0) then
            call set_error(st, STATUS_MODEL_ERROR, merge('CARA   ', 'REPERE ', what == ' ') &
                // trim(merge(cara_name, repere, what == ' ')) // ' is not supported ' // &
                '(CARA: K_, M_ or A_ then T_ or TR_, D_ for a diagonal, N or L; ' // &
                'REPERE: GLOBAL, LOCAL)')
            return
        end if
        n = inertia_value_count(cara_name, two_d, sym)
        if (size(values) /= n) then
            call set_error(st, STATUS_MODEL_ERROR, keyword // ' ' // to_upper(trim(cara_name)) &
                // ' needs ' // to_text(n) // ' values in VALE, got ' // &
                to_text(size(values, kind=i4)))
            return
        end if
        matrix = 0
        if (what == 'K' .and. .not. diagonal) then
            n = discrete_node_dofs(rotational, two_d) * merge(2, 1, on_link)
            call discrete_full_matrix(values, n, sym, k)
        end if
        do i = 1, size(cells)
            c = cells(i)
            if (.not. check_all .and. .not. is_discrete(model%element(c))) then
                skipped = skipped + 1       ! Code_Aster's default: passed over (vafcar)
                cycle
            end if
            reason = discrete_misfit(model, mesh, c, code, keyword, group, cara_name)
            if (len(reason) > 0) then
                call set_error(st, STATUS_MODEL_ERROR, reason)
                return
            end if
            if (what == 'M') cara%has_mass(c) = any(abs(values) > 0.0_dp)
            if (what /= 'K') cycle
            if (.not. diagonal .and. matrix == 0) call store_matrix(k, matrix)
            cara%discrete_cara(c) = code
            cara%discrete_repere(c) = rep
            cara%discrete_values(:, c) = 0.0_dp
            cara%discrete_matrix(c) = matrix
            if (diagonal) cara%discrete_values(1:size(values), c) = values
        end do
        if (present(n_skipped)) n_skipped = skipped
    contains
        subroutine store_matrix(k, index)
            real(dp), intent(in) :: k(:, :)
            integer(i4), intent(out) :: index
            type(discrete_matrix_t), allocatable :: bigger(:)
            if (cara%n_matrices == size(cara%matrices)) then
                allocate (bigger(2 * size(cara%matrices)))
                bigger(1:cara%n_matrices) = cara%matrices(1:cara%n_matrices)
                call move_alloc(bigger, cara%matrices)
            end if
            cara%n_matrices = cara%n_matrices + 1
            cara%matrices(cara%n_matrices)%k = k
            ! exact comparison: any difference is the user's K and is solved for
            cara%matrices(cara%n_matrices)%symmetric = .not. any(abs(k - transpose(k)) > 0.0_dp)
            index = cara%n_matrices
        end subroutine store_matrix
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

    !> MASSIF: the material frame on the plane solid cells among `cells` (the others, edges
    !> or plates, passed over; their number returned).
    !>  kind   : in, MASSIF_ANGL_REP, MASSIF_ANGL_EULER or MASSIF_AXE
    !>  values : in, up to 5 values (angles, then ORIG_AXE for MASSIF_AXE)
    subroutine assign_massif(cara, model, cells, kind, values, n_skipped)
        type(cara_elem_t), intent(inout) :: cara
        type(model_t), intent(in) :: model
        integer(i4), intent(in) :: cells(:), kind
        real(dp), intent(in) :: values(:)
        integer(i4), intent(out) :: n_skipped
        integer(i4) :: i, c, n
        n = min(5, size(values))
        n_skipped = 0
        do i = 1, size(cells)
            c = cells(i)
            if (.not. is_plane_solid(model%element(c))) then
                n_skipped = n_skipped + 1
                cycle
            end if
            cara%massif_kind(c) = kind
            cara%massif_values(:, c) = 0.0_dp
            cara%massif_values(1:n, c) = values(1:n)
        end do
    end subroutine assign_massif

    !> The angle (radians) of the material axis L of plane cell c from global X (Code_Aster's
    !> rcangm in 2D): 0 without MASSIF; ANGL_REP's first angle (about Z); the in-plane angle
    !> of the L axis of ANGL_EULER's rotation (the first column of the Euler matrix, eulnau);
    !> ORIG_AXE: the direction from the axis (along Z through ORIG_AXE) to the mean of the
    !> cell's nodes (getElemOrientation).
    !>  st : out, STATUS_MODEL_ERROR when that centre is on the axis, or the Euler angles
    !>       turn L along Z (no in-plane direction); the caller names the cell
    subroutine material_axis_angle(mesh, cara, c, alpha, st)
        type(mesh_t), intent(in) :: mesh
        type(cara_elem_t), intent(in) :: cara
        integer(i4), intent(in) :: c
        real(dp), intent(out) :: alpha
        type(status_t), intent(out) :: st
        real(dp), parameter :: DEGREE = acos(-1.0_dp) / 180.0_dp
        real(dp) :: centre(2), r(2), size2, e(3), xl(2)
        integer(i4) :: p
        alpha = 0.0_dp
        select case (cara%massif_kind(c))
        case (MASSIF_ANGL_REP)
            alpha = cara%massif_values(1, c) * DEGREE
        case (MASSIF_ANGL_EULER)
            e = cara%massif_values(1:3, c) * DEGREE
            xl = [cos(e(3)) * cos(e(1)) - sin(e(3)) * cos(e(2)) * sin(e(1)), &
                  cos(e(3)) * sin(e(1)) + sin(e(3)) * cos(e(2)) * cos(e(1))]
            if (.not. norm2(xl) > 1.0e-12_dp) then
                call set_error(st, STATUS_MODEL_ERROR, 'MASSIF ANGL_EULER turns the L ' // &
                    'axis along Z: a plane element needs L in its plane')
                return
            end if
            alpha = atan2(xl(2), xl(1))
        case (MASSIF_AXE)
            centre = 0.0_dp
            size2 = 0.0_dp
            do p = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                centre = centre + mesh%coords(1:2, mesh%cell_nodes(p))
            end do
            centre = centre / real(mesh%cell_ptr(c + 1) - mesh%cell_ptr(c), dp)
            do p = mesh%cell_ptr(c), mesh%cell_ptr(c + 1) - 1
                size2 = max(size2, sum((mesh%coords(1:2, mesh%cell_nodes(p)) - centre)**2))
            end do
            r = centre - cara%massif_values(3:4, c)
            if (.not. sum(r**2) > 1.0e-24_dp * size2) then
                call set_error(st, STATUS_MODEL_ERROR, 'MASSIF ORIG_AXE: the axis goes ' // &
                    'through the centre of the cell, which then has no radial direction')
                return
            end if
            alpha = atan2(r(2), r(1))
        end select
    end subroutine material_axis_angle

end module model_cara_elem
