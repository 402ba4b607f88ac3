!> CREA_CHAMP OPERATION='DISC' (Code_Aster U4.72.04, crea_champ.py block b_disc: CHAM_GD
!> required, MODELE optional): the field CHAM_GD moved to another location (TYPE_CHAM), the
!> same quantity and components:
!>   ELEM, CART -> ELNO, ELGA, ELEM  the cell's value at every point of the cell;
!>   NOEU -> ELNO                    each cell's nodes' values;
!>   NOEU -> ELGA                    interpolated at the cell's RIGI points with its shape
!>                                   functions (sum_a N_a(xi_g) v_a);
!>   ELGA -> ELNO                    extrapolated as CALC_CHAMP's *_ELNO (field_transforms);
!>   ELNO -> NOEU                    the mean over the cells around each node, as *_NOEU.
!> Element targets are on the cells of the model (MODELE, else the field's) that carry an
!> element; a cell gets the components the source has there (for NOEU: those every node of
!> the cell has). OPTION (Code_Aster: the option whose family the ELGA points follow) is
!> accepted: parasol's element fields all have their points on RIGI (field_layout).
!> Errors: CHAM_GD not a field, TYPE_CHAM of another quantity (naming the field's), an
!> element target without a model, a source with sub-points (plate layers), a move not
!> listed above (naming those that are).
module crea_champ_disc
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, clear_status, STATUS_MODEL_ERROR, &
        STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use mesh_types, only: mesh_t
    use mesh_cell_shapes, only: cell_shape, MAX_CELL_NODES
    use model_types, only: model_t
    use field_types, only: field_t, component_set_t, field_init_cells, field_define_cells, &
        field_type_cham, FIELD_NOEU, FIELD_ELGA, FIELD_ELNO, FIELD_ELEM, FIELD_CART, &
        FIELD_LOCATION_NAMES
    use field_concept, only: field_concept_t
    use field_layout, only: element_point_count, element_points
    use field_support, only: mesh_of_support, model_of_support
    use field_transforms, only: gauss_to_nodes, nodes_average
    use element_gauss_families, only: gauss_rule_t
    use crea_champ_combine, only: read_support, component_sets_of
    implicit none
    private

    character(len=*), parameter :: MOVES_BUILT = 'ELEM or CART to ELNO, ELGA, ELEM; ' // &
        'NOEU to ELNO, ELGA; ELGA to ELNO; ELNO to NOEU'

    public :: crea_disc

contains

    !> OPERATION='DISC' (module header) into `out`, of `location` and `quantity`.
    subroutine crea_disc(cmd, location, quantity, out, st)
        type(command_t), intent(in) :: cmd
        integer(i4), intent(in) :: location
        character(len=*), intent(in) :: quantity
        type(field_concept_t), intent(inout) :: out
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        integer(i4) :: from
        if (.not. cmd%has('CHAM_GD')) then
            call cmd%error_at('OPERATION', 'OPERATION=''DISC'' moves the field CHAM_GD: ' // &
                'give it', st, STATUS_MODEL_ERROR)
            return
        end if
        call cmd%get_concept('CHAM_GD', p, st)
        if (st%failed()) return
        select type (p)
        type is (field_concept_t)
            if (p%field%quantity /= quantity) then
                call cmd%error_at('TYPE_CHAM', 'CHAM_GD is a ' // field_type_cham(p%field) // &
                    ': DISC changes where a field lives, not its quantity (give ' // &
                    FIELD_LOCATION_NAMES(location) // '_' // p%field%quantity // ')', st, &
                    STATUS_MODEL_ERROR)
                return
            end if
            if (cmd%has('MODELE')) then
                call read_support(cmd, out, mesh, model, st)
                if (st%failed()) return
            else
                out%support => p%support
                out%model => p%model
                call mesh_of_support(p%support, mesh, st)
                if (st%failed()) then
                    call relocate(cmd, 'CHAM_GD', st)
                    return
                end if
                call model_of_support(p%model, model)
                if (.not. associated(model)) call model_of_support(p%support, model)
            end if
            if (p%field%location /= FIELD_NOEU) then
                if (p%field%n_cells /= mesh%n_cells) then
                    call cmd%error_at('MODELE', 'CHAM_GD lives on another mesh (' // &
                        'its cells are not the model''s)', st, STATUS_MODEL_ERROR)
                    return
                end if
                if (any(p%field%n_subpoints > 1 .and. p%field%n_points > 0)) then
                    call cmd%error_at('CHAM_GD', 'CHAM_GD has sub-points (plate layers): ' // &
                        'DISC moves fields of one sub-point; extract a layer first ' // &
                        '(POST_CHAMP EXTR_COQUE)', st, STATUS_NOT_IMPLEMENTED)
                    return
                end if
            else if (p%field%n_nodes /= mesh%n_nodes) then
                call cmd%error_at('MODELE', 'CHAM_GD lives on another mesh (its nodes ' // &
                    'are not the model''s)', st, STATUS_MODEL_ERROR)
                return
            end if
            if (location /= FIELD_NOEU .and. location /= FIELD_CART .and. &
                .not. associated(model)) then
                call cmd%error_at('OPERATION', FIELD_LOCATION_NAMES(location) // ' fields ' // &
                    'are defined on the elements of a model: give MODELE', st, &
                    STATUS_MODEL_ERROR)
                return
            end if
            from = p%field%location
            if ((from == FIELD_ELEM .or. from == FIELD_CART) .and. (location == FIELD_ELNO &
                .or. location == FIELD_ELGA .or. location == FIELD_ELEM)) then
                call from_cells(p%field, mesh, model, location, out%field, st)
            else if (from == FIELD_NOEU .and. (location == FIELD_ELNO .or. &
                     location == FIELD_ELGA)) then
                call from_nodes(p%field, mesh, model, location, out%field, st)
            else if (from == FIELD_ELGA .and. location == FIELD_ELNO) then
                call gauss_to_nodes(p%field, mesh, model, out%field, st)
            else if (from == FIELD_ELNO .and. location == FIELD_NOEU) then
                call nodes_average(p%field, mesh, out%field, st)
            else
                call cmd%error_at('TYPE_CHAM', 'DISC from ' // FIELD_LOCATION_NAMES(from) // &
                    ' to ' // FIELD_LOCATION_NAMES(location) // ' is not built in parasol (' // &
                    MOVES_BUILT // ' are)', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
            if (st%failed()) call relocate(cmd, 'CHAM_GD', st)
        class default
            call cmd%error_at('CHAM_GD', 'expected a field (cham_no, cham_elem, carte), ' // &
                'got ' // p%type_name(), st, STATUS_MODEL_ERROR)
        end select
    end subroutine crea_disc

    ! ELEM / CART -> ELNO, ELGA, ELEM: the cell's value at each point of the cell.
    subroutine from_cells(src, mesh, model, location, f, st)
        type(field_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        integer(i4), intent(in) :: location
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        integer(i4) :: c, k, n_cmp
        integer(i8) :: a, b
        call field_init_cells(f, location, src%quantity, src%components, mesh%n_cells, st)
        if (st%failed()) return
        allocate (n_points(mesh%n_cells), n_sub(mesh%n_cells), cell_set(mesh%n_cells), &
            source=0_i4)
        n_sub = 1
        do c = 1, mesh%n_cells
            if (src%n_points(c) == 0) cycle
            n_points(c) = element_point_count(model%element(c), mesh%cell_type(c), location)
            if (n_points(c) > 0) cell_set(c) = src%cell_set(c)
        end do
        call require_some(n_points, st)
        if (st%ok()) call field_define_cells(f, n_points, n_sub, cell_set, src%sets, st)
        if (st%failed()) return
        do c = 1, mesh%n_cells
            if (n_points(c) == 0) cycle
            n_cmp = size(src%sets(cell_set(c))%cmp, kind=i4)
            a = src%offset(c)
            do k = 1, n_points(c)
                b = f%offset(c) + int(k - 1, i8) * n_cmp
                f%values(b + 1:b + n_cmp) = src%values(a + 1:a + n_cmp)
            end do
        end do
    end subroutine from_cells

    ! NOEU -> ELNO (the nodes' values) or ELGA (interpolated at the RIGI points).
    subroutine from_nodes(src, mesh, model, location, f, st)
        type(field_t), intent(in) :: src
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        integer(i4), intent(in) :: location
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        type(component_set_t), allocatable :: sets(:)
        logical, allocatable :: assigned(:, :)
        type(gauss_rule_t) :: rule
        real(dp) :: shape(MAX_CELL_NODES), dshape(2, MAX_CELL_NODES)
        integer(i4) :: c, k, j, nn, p0, n_cmp, cmp, a
        integer(i8) :: b
        call field_init_cells(f, location, src%quantity, src%components, mesh%n_cells, st)
        if (st%failed()) return
        allocate (n_points(mesh%n_cells), n_sub(mesh%n_cells), source=0_i4)
        allocate (assigned(size(src%components), mesh%n_cells), source=.false.)
        n_sub = 1
        do c = 1, mesh%n_cells
            n_points(c) = element_point_count(model%element(c), mesh%cell_type(c), location)
            if (n_points(c) == 0) cycle
            p0 = mesh%cell_ptr(c)
            nn = mesh%cell_ptr(c + 1) - p0
            assigned(:, c) = all(src%node_has(:, mesh%cell_nodes(p0:p0 + nn - 1)), dim=2)
            if (.not. any(assigned(:, c))) n_points(c) = 0
        end do
        call require_some(n_points, st)
        if (st%failed()) return
        call component_sets_of(assigned, cell_set, sets)
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do c = 1, mesh%n_cells
            if (n_points(c) == 0) cycle
            p0 = mesh%cell_ptr(c)
            nn = mesh%cell_ptr(c + 1) - p0
            n_cmp = size(sets(cell_set(c))%cmp, kind=i4)
            if (location == FIELD_ELGA) then
                call element_points(model%element(c), mesh%cell_type(c), n_points(c), rule, st)
                if (st%failed()) return
            end if
            do k = 1, n_points(c)
                b = f%offset(c) + int(k - 1, i8) * n_cmp
                if (location == FIELD_ELNO) then
                    do j = 1, n_cmp
                        cmp = sets(cell_set(c))%cmp(j)
                        f%values(b + j) = src%node_values(cmp, mesh%cell_nodes(p0 + k - 1))
                    end do
                else
                    call cell_shape(mesh%cell_type(c), rule%xi(1, k), rule%xi(2, k), &
                        shape, dshape)
                    do j = 1, n_cmp
                        cmp = sets(cell_set(c))%cmp(j)
                        f%values(b + j) = 0.0_dp
                        do a = 1, nn
                            f%values(b + j) = f%values(b + j) + shape(a) * &
                                src%node_values(cmp, mesh%cell_nodes(p0 + a - 1))
                        end do
                    end do
                end if
            end do
        end do
    end subroutine from_nodes

    ! An element target must land on some cell.
    subroutine require_some(n_points, st)
        integer(i4), intent(in) :: n_points(:)
        type(status_t), intent(out) :: st
        if (all(n_points == 0)) call set_error(st, STATUS_MODEL_ERROR, 'no cell of the ' // &
            'field carries an element of the model with these points: the field would be empty')
    end subroutine require_some

    ! Locates a failed status at `key`, keeping its message and category.
    subroutine relocate(kws, key, st)
        class(keyword_set_t), intent(in) :: kws
        character(len=*), intent(in) :: key
        type(status_t), intent(inout) :: st
        character(len=:), allocatable :: message
        integer :: code
        message = st%message
        code = st%code
        if (code /= STATUS_NOT_IMPLEMENTED) code = STATUS_MODEL_ERROR
        call clear_status(st)
        call kws%error_at(key, message, st, code)
    end subroutine relocate

end module crea_champ_disc
