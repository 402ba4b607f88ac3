!> Mechanical loads: the content of a char_meca concept (AFFE_CHAR_MECA / AFFE_CHAR_MECA_F).
!>
!> A load set is a list of items, each of one kind applied to nodes or cells:
!>   DDL_IMPO      nodes, imposed components DX..DRZ
!>   FORCE_NODALE  nodes, FX FY FZ MX MY MZ (added to the equations DX..DRZ)
!>   FORCE_NODALE  (ANGL_NAUT: FX..MZ in the frame of the nautical angles)
!>   FORCE_COQUE   plate cells, PRES (force = -PRES n), FX..MZ (global) or F1, F2, F3,
!>                 MF1, MF2 (the plate's user frame) per unit area, on the plane PLAN
!>   PRES_REP      plate cells, PRES; plane edges (SEG2, SEG3), PRES and CISA_2D
!>   FORCE_CONTOUR SEG2/SEG3 edge cells of plane models, FX FY per unit length (unit depth)
!>   FORCE_ARETE   SEG2 edges of a DKT model, FX..MZ per unit length (global)
!>   FORCE_INTERNE plane solid cells, FX FY per unit volume (unit depth)
!>   PESANTEUR     cells (all, or GROUP_MA): rho g d per unit volume (plates: rho EPAIS g d
!>                 per unit area), slots 1..3 = g d (d the unit DIRECTION)
!>   RELATION      linear relations between components of nodes (LIAISON_DDL,
!>                 LIAISON_OBLIQUE, LIAISON_UNIF, LIAISON_SOLIDE, LIAISON_GROUP,
!>                 LIAISON_RBE3, LIAISON_MAIL, FACE_IMPO and ARETE_IMPO DNOR/DTAN): each
!>                 relation sum_k a_k u(node_k, comp_k) = beta, beta the value of one slot
!>                 (COEF_IMPO, DNOR, DX of an oblique frame ...) evaluated at one node, or 0;
!>                 the occurrence's keyword names the item. The analysis eliminates them
!>                 (assembly_relations, doc/analysis.md "Linear relations").
!> Each of the six slots of an item holds either a real constant (AFFE_CHAR_MECA) or a
!> function of (INST, X, Y, Z) (AFFE_CHAR_MECA_F). A function slot keeps a POINTER to a
!> function concept owned by the run context (the deck's symbol table): the load set never
!> owns or frees it, and it must not outlive the run context. Functions are bound to the
!> parameter names LOAD_PARAMETERS once, when the slot is set.
!> Plate loads are evaluated at the cell's nodes, edge loads at the edge's Gauss points
!> (assembly layer, as Code_Aster), nodal ones at the node, always with INST = the end of the
!> step. A kinematic set (AFFE_CHAR_CINE / AFFE_CHAR_CINE_F) holds DDL_IMPO items only: its
!> values are eliminated like DDL_IMPO's (parasol eliminates both), and it may not impose an
!> equation another load imposes too. A BLOCAGE item (DDL_IMPO/BLOCAGE) imposes 0 on the
!> components each of its nodes has, skipping the others (Code_Aster caddli).
module model_loads
    use kinds, only: dp, i4
    use status, only: status_t, set_error, add_context, STATUS_MODEL_ERROR
    use strings, only: to_text
    use number_limits, only: MAX_LENGTH, is_finite, magnitude_fits
    use function_concept, only: function_concept_t, param_binding_t
    use result_fields, only: result_fields_t, result_field_index
    use field_types, only: field_component
    implicit none
    private

    integer(i4), parameter, public :: LOAD_DDL_IMPO = 1, LOAD_FORCE_NODALE = 2, &
        LOAD_FORCE_COQUE = 3, LOAD_PRES_REP = 4, LOAD_FORCE_CONTOUR = 5, LOAD_RELATION = 6, &
        LOAD_FORCE_ARETE = 7, LOAD_FORCE_INTERNE = 8, LOAD_PESANTEUR = 9, &
        LOAD_PRE_EPSI = 10, LOAD_PRE_EPSI_PLATE = 11, N_LOAD_KINDS = 11
    character(len=13), parameter, public :: LOAD_KIND_NAMES(N_LOAD_KINDS) = [ &
        'DDL_IMPO     ', 'FORCE_NODALE ', 'FORCE_COQUE  ', 'PRES_REP     ', &
        'FORCE_CONTOUR', 'LIAISON      ', 'FORCE_ARETE  ', 'FORCE_INTERNE', 'PESANTEUR    ', &
        'PRE_EPSI     ', 'PRE_EPSI     ']
    !> Value slots of an item (see load_item_t%values).
    integer(i4), parameter, public :: MAX_SLOTS = 9
    !> Slot of PRES in FORCE_COQUE / PRES_REP items, of CISA_2D in PRES_REP items, and the
    !> first of FORCE_NODALE's three ANGL_NAUT angles (the FX .. MZ slots are 1..6).
    integer(i4), parameter, public :: SLOT_PRES = 7, SLOT_CISA = 8, SLOT_ANGLES = 7
    !> FORCE_COQUE/PLAN: the plane the forces act in (Code_Aster te0032: MAIL and MOY the
    !> mean surface, SUP and INF the faces at +-EPAIS/2, a moment of the in-plane forces).
    integer(i4), parameter, public :: PLAN_MAIL = 0, PLAN_SUP = 1, PLAN_INF = -1, &
        PLAN_MOY = 2
    !> Names of the slots of each kind (messages).
    character(len=9), parameter :: SLOT_NAMES(MAX_SLOTS, N_LOAD_KINDS) = reshape( &
        [character(len=9) :: &
        'DX', 'DY', 'DZ', 'DRX', 'DRY', 'DRZ', '', '', '', &
        'FX', 'FY', 'FZ', 'MX', 'MY', 'MZ', 'ANGL_NAUT', 'ANGL_NAUT', 'ANGL_NAUT', &
        'FX', 'FY', 'FZ', 'MX', 'MY', 'MZ', 'PRES', '', '', &
        '', '', '', '', '', '', 'PRES', 'CISA_2D', '', &
        'FX', 'FY', 'FZ', '', '', '', '', '', '', &
        '', '', '', '', '', '', '', '', '', &
        'FX', 'FY', 'FZ', 'MX', 'MY', 'MZ', '', '', '', &
        'FX', 'FY', 'FZ', '', '', '', '', '', '', &
        'GRAVITE', 'GRAVITE', 'GRAVITE', '', '', '', '', '', '', &
        'EPXX', 'EPYY', 'EPZZ', 'EPXY', '', '', '', '', '', &
        'EXX', 'EYY', 'EXY', 'KXX', 'KYY', 'KXY', '', '', ''], [MAX_SLOTS, N_LOAD_KINDS])
    !> Parameter names every load function is bound to, in the order of the value arrays.
    character(len=4), parameter, public :: LOAD_PARAMETERS(4) = ['INST', 'X   ', 'Y   ', &
        'Z   ']
    !> PRES_REP's functions also see the current position of the point, XF, YF, ZF (Code_Aster
    !> evalPressureSetFuncPara): the deformed geometry for a follower load (STAT_NON_LINE
    !> EXCIT TYPE_CHARGE='SUIV'), 0 otherwise, as in Code_Aster.
    character(len=4), parameter, public :: PRESSURE_PARAMETERS(7) = ['INST', 'X   ', &
        'Y   ', 'Z   ', 'XF  ', 'YF  ', 'ZF  ']

    !> One value: a constant or a function of (INST, X, Y, Z).
    type, public :: load_value_t
        logical :: given = .false.
        real(dp) :: constant = 0.0_dp
        class(function_concept_t), pointer :: func => null()   !< not owned (run context)
        type(param_binding_t) :: binding
        !> EVOL_IMPO (AFFE_CHAR_CINE): component `evol_cmp` of DEPL at node `evol_node` of
        !> the result `evol`, interpolated linearly in INST between its stored instants
        class(result_fields_t), pointer :: evol => null()      !< not owned (run context)
        integer(i4) :: evol_node = 0
        character(len=8) :: evol_cmp = ''
    end type load_value_t

    !> One occurrence of a load keyword.
    type, public :: load_item_t
        integer(i4) :: kind = 0                      !< LOAD_*
        integer(i4), allocatable :: nodes(:)         !< DDL_IMPO, FORCE_NODALE
        integer(i4), allocatable :: cells(:)         !< FORCE_COQUE, PRES_REP, FORCE_CONTOUR
        !> DX..DRZ / FX..MZ (FORCE_NODALE: then ANGL_NAUT) / FORCE_COQUE FX..MZ or F1, F2,
        !> F3, MF1, MF2 (local_frame), PRES / PRES_REP PRES, CISA_2D / PESANTEUR g d
        type(load_value_t) :: values(MAX_SLOTS)
        character(len=:), allocatable :: group      !< group name, for messages
        !> where the occurrence is in the deck (errors found while the load is applied are
        !> located there): file, line, column, command (AFFE_CHAR_MECA_F) and keyword
        character(len=:), allocatable :: file, command, keyword
        integer(i4) :: line = 0, col = 0
        logical :: blocage = .false.                 !< DDL_IMPO/BLOCAGE: skip absent components
        !> FORCE_COQUE F1, F2, F3, MF1, MF2: in the plate's user frame (COQUE/ANGL_REP)
        logical :: local_frame = .false.
        integer(i4) :: plan = PLAN_MAIL               !< FORCE_COQUE/PLAN (PLAN_*)
        !> FORCE_COQUE_FO: PRES of each of `cells` (same order), a constant per cell
        !> evaluated when the load is defined (force_coque_fo; Code_Aster char_eval_fonc)
        real(dp), allocatable :: cell_pres(:)
        logical :: angles = .false.                   !< FORCE_NODALE/ANGL_NAUT given
        !> RELATION items: relation r has the terms rel_ptr(r) .. rel_ptr(r+1)-1 of
        !> (rel_node, rel_comp, rel_coef); its right-hand side is values(rel_slot(r))
        !> evaluated at node rel_at(r) (rel_slot 0: zero)
        integer(i4) :: n_rel = 0
        integer(i4), allocatable :: rel_ptr(:), rel_node(:), rel_comp(:), rel_slot(:), &
            rel_at(:)
        real(dp), allocatable :: rel_coef(:)
        !> LIAISON_SOLIDE: the nodes of the rigid body (its cells store no energy)
        integer(i4), allocatable :: solid_nodes(:)
        !> names of the value slots, for messages (RELATION items: COEF_IMPO, DNOR, ...)
        character(len=16) :: slot_names(MAX_SLOTS) = ''
    end type load_item_t

    !> A char_meca concept's content.
    type, public :: load_set_t
        integer(i4) :: n_items = 0
        type(load_item_t), allocatable :: items(:)
        logical :: kinematic = .false.               !< AFFE_CHAR_CINE(_F)
    end type load_set_t

    public :: load_add_item, load_set_constant, load_set_function, load_set_cell_pressures, load_value_at, &
        load_has_kind, load_set_location, load_locate, load_item_where, load_slot_name, &
        load_add_relation, item_slot_name

contains

    !> Appends an empty item of a kind on nodes or cells; returns its index.
    !>  set   : inout, the load set
    !>  kind  : in, LOAD_*
    !>  ids   : in, node numbers (DDL_IMPO, FORCE_NODALE) or cell numbers (others)
    !>  index : out, the new item's index
    !>  group : in, optional group name for messages
    subroutine load_add_item(set, kind, ids, index, group)
        type(load_set_t), intent(inout) :: set
        integer(i4), intent(in) :: kind, ids(:)
        integer(i4), intent(out) :: index
        character(len=*), intent(in), optional :: group
        type(load_item_t), allocatable :: grown(:)
        integer(i4) :: k
        if (.not. allocated(set%items)) allocate (set%items(4))
        if (set%n_items == size(set%items)) then
            allocate (grown(2 * size(set%items)))
            do k = 1, set%n_items
                call move_item(set%items(k), grown(k))
            end do
            call move_alloc(grown, set%items)
        end if
        set%n_items = set%n_items + 1
        index = set%n_items
        set%items(index)%kind = kind
        if (kind == LOAD_DDL_IMPO .or. kind == LOAD_FORCE_NODALE) then
            set%items(index)%nodes = ids
            allocate (set%items(index)%cells(0))
        else
            set%items(index)%cells = ids
            allocate (set%items(index)%nodes(0))
        end if
        set%items(index)%group = ''
        if (present(group)) set%items(index)%group = group
    end subroutine load_add_item

    !> Moves an item component by component (no derived-type assignment of the whole).
    subroutine move_item(from, to)
        type(load_item_t), intent(inout) :: from
        type(load_item_t), intent(inout) :: to
        integer(i4) :: k
        to%kind = from%kind
        to%blocage = from%blocage
        to%local_frame = from%local_frame
        to%plan = from%plan
        to%angles = from%angles
        call move_alloc(from%nodes, to%nodes)
        call move_alloc(from%cells, to%cells)
        if (allocated(from%cell_pres)) call move_alloc(from%cell_pres, to%cell_pres)
        to%n_rel = from%n_rel
        if (allocated(from%rel_ptr)) call move_alloc(from%rel_ptr, to%rel_ptr)
        if (allocated(from%rel_node)) call move_alloc(from%rel_node, to%rel_node)
        if (allocated(from%rel_comp)) call move_alloc(from%rel_comp, to%rel_comp)
        if (allocated(from%rel_coef)) call move_alloc(from%rel_coef, to%rel_coef)
        if (allocated(from%rel_slot)) call move_alloc(from%rel_slot, to%rel_slot)
        if (allocated(from%rel_at)) call move_alloc(from%rel_at, to%rel_at)
        if (allocated(from%solid_nodes)) call move_alloc(from%solid_nodes, to%solid_nodes)
        to%slot_names = from%slot_names
        call move_alloc(from%group, to%group)
        if (allocated(from%file)) call move_alloc(from%file, to%file)
        if (allocated(from%command)) call move_alloc(from%command, to%command)
        if (allocated(from%keyword)) call move_alloc(from%keyword, to%keyword)
        to%line = from%line
        to%col = from%col
        do k = 1, MAX_SLOTS
            to%values(k)%given = from%values(k)%given
            to%values(k)%constant = from%values(k)%constant
            to%values(k)%func => from%values(k)%func
            to%values(k)%evol => from%values(k)%evol
            to%values(k)%evol_node = from%values(k)%evol_node
            to%values(k)%evol_cmp = from%values(k)%evol_cmp
            if (allocated(from%values(k)%binding%slot)) &
                call move_alloc(from%values(k)%binding%slot, to%values(k)%binding%slot)
            if (allocated(from%values(k)%binding%names)) &
                call move_alloc(from%values(k)%binding%names, to%values(k)%binding%names)
            if (allocated(from%values(k)%binding%provided)) call move_alloc( &
                from%values(k)%binding%provided, to%values(k)%binding%provided)
        end do
    end subroutine move_item

    !> Appends one relation sum_k coefs(k) u(nodes(k), comps(k)) = beta to RELATION item
    !> `index`, beta being slot `slot` evaluated at node `at` (slot 0: beta = 0).
    subroutine load_add_relation(set, index, nodes, comps, coefs, slot, at)
        type(load_set_t), intent(inout) :: set
        integer(i4), intent(in) :: index, nodes(:), comps(:), slot, at
        real(dp), intent(in) :: coefs(:)
        integer(i4) :: n, m
        associate (item => set%items(index))
            if (.not. allocated(item%rel_ptr)) then
                allocate (item%rel_ptr(17), item%rel_slot(16), item%rel_at(16))
                allocate (item%rel_node(64), item%rel_comp(64), item%rel_coef(64))
                item%rel_ptr(1) = 1
            end if
            n = item%n_rel
            m = item%rel_ptr(n + 1) - 1
            if (n + 1 > size(item%rel_slot)) then
                call grow_int(item%rel_ptr, 2 * size(item%rel_slot) + 1)
                call grow_int(item%rel_slot, 2 * size(item%rel_slot))
                call grow_int(item%rel_at, 2 * size(item%rel_at))
            end if
            if (m + size(nodes) > size(item%rel_node)) then
                call grow_int(item%rel_node, 2 * (m + size(nodes)))
                call grow_int(item%rel_comp, 2 * (m + size(nodes)))
                call grow_real(item%rel_coef, 2 * (m + size(nodes)))
            end if
            item%rel_node(m + 1:m + size(nodes)) = nodes
            item%rel_comp(m + 1:m + size(nodes)) = comps
            item%rel_coef(m + 1:m + size(nodes)) = coefs
            item%n_rel = n + 1
            item%rel_ptr(n + 2) = m + size(nodes, kind=i4) + 1
            item%rel_slot(n + 1) = slot
            item%rel_at(n + 1) = at
        end associate
    end subroutine load_add_relation

    subroutine grow_int(a, n)
        integer(i4), allocatable, intent(inout) :: a(:)
        integer, intent(in) :: n
        integer(i4), allocatable :: b(:)
        allocate (b(n), source=0_i4)
        b(1:size(a)) = a
        call move_alloc(b, a)
    end subroutine grow_int

    subroutine grow_real(a, n)
        real(dp), allocatable, intent(inout) :: a(:)
        integer, intent(in) :: n
        real(dp), allocatable :: b(:)
        allocate (b(n), source=0.0_dp)
        b(1:size(a)) = a
        call move_alloc(b, a)
    end subroutine grow_real

    !> Name of slot `slot` of an item: its own names (RELATION items), else its kind's.
    pure function item_slot_name(item, slot) result(name)
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: slot
        character(len=:), allocatable :: name
        name = trim(item%slot_names(slot))
        if (len(name) == 0) name = load_slot_name(item%kind, slot)
    end function item_slot_name

    !> Sets slot `slot` (1..MAX_SLOTS) of item `index` to a constant.
    subroutine load_set_constant(set, index, slot, value)
        type(load_set_t), intent(inout) :: set
        integer(i4), intent(in) :: index, slot
        real(dp), intent(in) :: value
        set%items(index)%values(slot)%given = .true.
        set%items(index)%values(slot)%constant = value
        set%items(index)%values(slot)%func => null()
    end subroutine load_set_constant

    !> Sets the PRES slot of item `index` to one constant per cell of the item
    !> (FORCE_COQUE_FO, evaluated at the cells' centres), values(k) for cells(k).
    subroutine load_set_cell_pressures(set, index, values)
        type(load_set_t), intent(inout) :: set
        integer(i4), intent(in) :: index
        real(dp), intent(in) :: values(:)
        set%items(index)%values(SLOT_PRES)%given = .true.
        set%items(index)%values(SLOT_PRES)%func => null()
        set%items(index)%values(SLOT_PRES)%constant = 0.0_dp
        set%items(index)%cell_pres = values
    end subroutine load_set_cell_pressures

    !> Sets slot `slot` of item `index` to a function of (INST, X, Y, Z), bound once here.
    !>  func : in, target owned by the run context (see the module header)
    subroutine load_set_function(set, index, slot, func)
        type(load_set_t), intent(inout) :: set
        integer(i4), intent(in) :: index, slot
        class(function_concept_t), intent(in), target :: func
        set%items(index)%values(slot)%given = .true.
        set%items(index)%values(slot)%func => func
        if (set%items(index)%kind == LOAD_PRES_REP) then
            call func%bind(PRESSURE_PARAMETERS, set%items(index)%values(slot)%binding)
        else
            call func%bind(LOAD_PARAMETERS, set%items(index)%values(slot)%binding)
        end if
    end subroutine load_set_function

    !> Records where item `index` is in the deck (see load_item_t).
    subroutine load_set_location(set, index, file, line, col, command, keyword)
        type(load_set_t), intent(inout) :: set
        integer(i4), intent(in) :: index, line, col
        character(len=*), intent(in) :: file, command, keyword
        set%items(index)%file = file
        set%items(index)%line = line
        set%items(index)%col = col
        set%items(index)%command = command
        set%items(index)%keyword = keyword
    end subroutine load_set_location

    !> Locates a failed status at item's occurrence and slot keyword, unless it already
    !> has a location (a formula's error is located inside the formula).
    subroutine load_locate(item, slot, st)
        type(load_item_t), intent(in) :: item
        integer(i4), intent(in) :: slot
        type(status_t), intent(inout) :: st
        if (st%ok() .or. .not. allocated(item%file)) return
        if (allocated(st%file)) return
        call add_context(st, file=item%file, line=item%line, column=item%col, &
                         command=item%command, keyword=item%keyword // '/' // &
                         item_slot_name(item, slot))
    end subroutine load_locate

    !> "deck.comm:53:24" of an item ('' when unknown), for messages naming two occurrences.
    function load_item_where(item) result(text)
        type(load_item_t), intent(in) :: item
        character(len=:), allocatable :: text
        text = ''
        if (.not. allocated(item%file)) return
        text = item%file // ':' // to_text(item%line) // ':' // to_text(item%col)
    end function load_item_where

    !> Name of slot `slot` of a load kind (DX, FZ, PRES, ...).
    pure function load_slot_name(kind, slot) result(name)
        integer(i4), intent(in) :: kind, slot
        character(len=:), allocatable :: name
        name = trim(SLOT_NAMES(slot, kind))
    end function load_slot_name

    !> Value of slot `slot` of a load of `kind` at time t and point x, checked: finite, and
    !> for DDL_IMPO and the right-hand sides of relations at most MAX_LENGTH in magnitude (a
    !> displacement or rotation that the products formed from it in the analysis cannot
    !> overflow), for the forces within the magnitude products may still be formed from
    !> (number_limits).
    !>  st : out, the function's evaluation error, with the load kind added; a value out of
    !>       range (then located by the caller with load_locate)
    !>  slot_name : in, optional, the slot's name in messages (default: the kind's)
    !>  x_current : in, optional, PRES_REP's XF, YF, ZF (PRESSURE_PARAMETERS; default 0)
    subroutine load_value_at(value, kind, slot, t, x, y, st, slot_name, x_current)
        type(load_value_t), intent(in) :: value
        integer(i4), intent(in) :: kind, slot
        real(dp), intent(in) :: t, x(3)
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: slot_name
        real(dp), intent(in), optional :: x_current(3)
        character(len=:), allocatable :: name
        real(dp) :: xf(3)
        y = value%constant
        if (associated(value%evol)) then
            call evol_value(value, t, y, st)
            if (st%failed()) then
                call set_error(st, STATUS_MODEL_ERROR, trim(LOAD_KIND_NAMES(kind)) // &
                    ' (EVOL_IMPO): ' &
                    // st%message)
                return
            end if
        else if (associated(value%func)) then
            xf = 0.0_dp
            if (present(x_current)) xf = x_current
            if (size(value%binding%provided) == size(PRESSURE_PARAMETERS)) then
                call value%func%evaluate(value%binding, [t, x(1), x(2), x(3), xf(1), xf(2), &
                    xf(3)], y, st)
            else
                call value%func%evaluate(value%binding, [t, x(1), x(2), x(3)], y, st)
            end if
            if (st%failed()) then
                call set_error(st, STATUS_MODEL_ERROR, LOAD_KIND_NAMES(kind) // ': ' // &
                    st%message)
                return
            end if
        end if
        name = load_slot_name(kind, slot)
        if (present(slot_name)) name = slot_name
        if (.not. is_finite(y)) then
            call set_error(st, STATUS_MODEL_ERROR, name // ' is not a finite number at INST ' &
                // to_text(t))
        else if ((kind == LOAD_DDL_IMPO .or. kind == LOAD_RELATION) .and. &
                 abs(y) > MAX_LENGTH) then
            call set_error(st, STATUS_MODEL_ERROR, name // ' = ' // to_text(y) // ' at INST ' &
                // to_text(t) // ' is out of range (|' // name // '| <= ' // &
                to_text(MAX_LENGTH) // ')')
        else if (.not. magnitude_fits(y)) then
            call set_error(st, STATUS_MODEL_ERROR, name // ' = ' // to_text(y) // ' at INST ' &
                // to_text(t) // ' is too large: the forces formed from it would overflow')
        end if
    end subroutine load_value_at

    !> EVOL_IMPO's value at INST t: DEPL of the result at the stored instant equal to t
    !> (within 1e-10 relative), else linear between the stored instants around t (Code_Aster
    !> interpolates the result in time the same way); t outside them is an error.
    subroutine evol_value(value, t, y, st)
        type(load_value_t), intent(in) :: value
        real(dp), intent(in) :: t
        real(dp), intent(out) :: y
        type(status_t), intent(out) :: st
        integer(i4) :: k, lo, hi
        real(dp) :: tol, w, y_lo, y_hi
        y = 0.0_dp
        associate (r => value%evol)
            if (r%n_stored == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'the result stores no instant')
                return
            end if
            tol = 1.0e-10_dp * max(1.0_dp, maxval(abs(r%inst(1:r%n_stored))))
            lo = 0
            hi = 0
            do k = 1, r%n_stored
                if (abs(r%inst(k) - t) <= tol) then
                    lo = k
                    hi = k
                    exit
                end if
                if (r%inst(k) < t) then
                    if (lo == 0) then
                        lo = k
                    else if (r%inst(k) > r%inst(lo)) then
                        lo = k
                    end if
                else
                    if (hi == 0) then
                        hi = k
                    else if (r%inst(k) < r%inst(hi)) then
                        hi = k
                    end if
                end if
            end do
            if (lo == 0 .or. hi == 0) then
                call set_error(st, STATUS_MODEL_ERROR, 'INST ' // to_text(t) // ' is outside ' &
                    // 'the instants of ' // r%name // ' (' // &
                    to_text(minval(r%inst(1:r%n_stored))) // ' to ' // &
                    to_text(maxval(r%inst(1:r%n_stored))) // ')')
                return
            end if
            call depl_at(lo, y_lo, st)
            if (st%ok()) call depl_at(hi, y_hi, st)
            if (st%failed()) return
            w = 0.0_dp
            if (hi /= lo) w = (t - r%inst(lo)) / (r%inst(hi) - r%inst(lo))
            y = (1.0_dp - w) * y_lo + w * y_hi
        end associate
    contains
        subroutine depl_at(at, v, st)
            integer(i4), intent(in) :: at
            real(dp), intent(out) :: v
            type(status_t), intent(out) :: st
            integer(i4) :: f, i
            v = 0.0_dp
            f = result_field_index(value%evol, at, 'DEPL')
            if (f == 0) then
                call set_error(st, STATUS_MODEL_ERROR, value%evol%name // ' has no DEPL at ' // &
                    'INST ' // to_text(value%evol%inst(at)))
                return
            end if
            associate (fd => value%evol%stored(at)%items(f)%field)
                i = field_component(fd, trim(value%evol_cmp))
                if (i == 0 .or. value%evol_node > fd%n_nodes) then
                    call set_error(st, STATUS_MODEL_ERROR, 'DEPL at INST ' // &
                        to_text(value%evol%inst(at)) // ' has no ' // trim(value%evol_cmp))
                    return
                end if
                if (.not. fd%node_has(i, value%evol_node)) then
                    call set_error(st, STATUS_MODEL_ERROR, 'DEPL at INST ' // &
                        to_text(value%evol%inst(at)) // ' has no ' // trim(value%evol_cmp) // &
                        ' at a node where another instant has it')
                    return
                end if
                v = fd%node_values(i, value%evol_node)
            end associate
        end subroutine depl_at
    end subroutine evol_value

    !> True when the set has an item of this kind.
    pure logical function load_has_kind(set, kind)
        type(load_set_t), intent(in) :: set
        integer(i4), intent(in) :: kind
        integer(i4) :: k
        load_has_kind = .false.
        do k = 1, set%n_items
            if (set%items(k)%kind == kind) load_has_kind = .true.
        end do
    end function load_has_kind

end module model_loads
