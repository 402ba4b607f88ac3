!> POST_ELEM VOLUMOGRAMME (U4.81.22): how the volume (or area) of a part of the model
!> shares out among intervals of one component's values, per stored instant, as Code_Aster's
!> pevolu / pebpct / chpond tabulate it:
!>  - the points: every value of NOM_CMP at the points (ELGA: Gauss points and sub-points;
!>    ELNO: nodes and sub-points) of the cells of TOUT or GROUP_MA (restricted to the cells of
!>    topological dimension TYPE_MAILLE when given), each with its weight: ELGA, the
!>    Gauss weight times the jacobian of the cell's map, and on a plate with layers (COQUE_NCOU
!>    of CARA_ELEM) times the layer's thickness h/n and Simpson's 1/6, 2/3, 1/6 for the
!>    bottom, middle and top sub-points (te0488's COOR_ELGA weight); ELNO, the cell's measure
!>    (times the same sub-point factor) divided by its number of nodes;
!>  - the intervals: NB_INTERV equal ones from the smallest value to the largest (or over
!>    BORNES, keeping only the values inside them), or two split at SEUIL; a value counts in
!>    the first interval when below its upper bound, in a middle one from its lower bound
!>    (included) to its upper one (excluded), in the last from its lower bound on;
!>  - DISTRIBUTION: 100 times the weights in the interval over their total (NORME='RELATIF')
!>    or the weights themselves (NORME='ABSOLU'); all values equal: 100 / NB_INTERV each,
!>    the bounds 0, as pebpct leaves them.
!> Columns RESULTAT, NOM_CHAM, NUME_ORDRE, INST, NOM_CMP, GROUP_MA ('-' for TOUT),
!> RESTRICTION (TYPE_MAILLE or '-'), INTERVALLE, BORNE_INF, BORNE_SUP, DISTRIBUTION.
!> Not built, each a located error: CHAM_GD, nodal fields (Code_Aster carries them to the
!> Gauss points first), SEUIL with BORNES.
module post_elem_volumogramme
    use kinds, only: dp, i4, i8
    use strings, only: to_text
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group
    use mesh_cell_shapes, only: CELL_TYPE_DIM, CELL_TYPE_NODES, MAX_CELL_NODES, cell_shape, &
        cell_geometric_measure
    use model_types, only: model_t, is_plate
    use model_concept, only: model_concept_t
    use model_cara_elem, only: cara_elem_t
    use cara_elem_concept, only: cara_elem_concept_t
    use analysis_result, only: result_concept_t
    use field_types, only: field_t, FIELD_ELGA, FIELD_ELNO, field_component, field_position, &
        field_location_name
    use result_fields, only: result_fields_t
    use result_access, only: result_field_at, result_mesh
    use result_instants, only: selected_instants
    use element_gauss_families, only: gauss_rule_t
    use field_layout, only: element_points
    use table_concept, only: table_t, table_add_column, table_add_rows, table_set_int, &
        table_set_real, table_set_text, TABLE_INT, TABLE_REAL, TABLE_TEXT
    use table_keywords, only: relocate_at
    use crea_table_command, only: result_of_occurrence
    implicit none
    private
    public :: volumogramme_rows

    !> Simpson's weights of a layer's bottom, middle and top sub-points (te0488's poidc).
    real(dp), parameter :: LEVEL_WEIGHTS(3) = [1.0_dp / 6.0_dp, 2.0_dp / 3.0_dp, &
        1.0_dp / 6.0_dp]
    !> parasol's bounds: intervals a table may hold, values the intervals are made of (so
    !> that the largest minus the smallest stays a finite double).
    integer, parameter :: MAX_INTERVALS = 100000
    real(dp), parameter :: VALUE_LIMIT = 1.0e300_dp

contains

    !> VOLUMOGRAMME: the table's columns and rows (module header).
    subroutine volumogramme_rows(cmd, t, st)
        type(command_t), intent(in) :: cmd
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        class(result_fields_t), pointer :: res
        type(mesh_t), pointer :: mesh
        type(model_t), pointer :: model
        integer, allocatable :: indices(:)
        logical :: by_inst
        integer :: k, j, c
        if (cmd%has('CHAM_GD')) then
            call cmd%error_at('CHAM_GD', 'VOLUMOGRAMME of a CHAM_GD is not built by ' // &
                'parasol: put the field in a result (CREA_RESU) and give RESULTAT', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        if (.not. cmd%has('RESULTAT')) then
            call cmd%error_at('VOLUMOGRAMME', 'VOLUMOGRAMME reads the field of a result: ' // &
                'give RESULTAT', st)
            return
        end if
        call result_of_occurrence(cmd, res, st)
        if (st%ok()) call selected_instants(cmd, res, indices, by_inst, st)
        if (st%ok()) call result_mesh(res, mesh, st)
        if (st%failed()) then
            call relocate_at(cmd, 'RESULTAT', st)
            return
        end if
        call model_of(cmd, res, model, st)
        if (st%failed()) return
        call table_add_column(t, 'RESULTAT', TABLE_TEXT, c, st, 8)
        call table_add_column(t, 'NOM_CHAM', TABLE_TEXT, c, st, 16)
        call table_add_column(t, 'NUME_ORDRE', TABLE_INT, c, st)
        call table_add_column(t, 'INST', TABLE_REAL, c, st)
        call table_add_column(t, 'NOM_CMP', TABLE_TEXT, c, st, 8)
        call table_add_column(t, 'GROUP_MA', TABLE_TEXT, c, st, 24)
        call table_add_column(t, 'RESTRICTION', TABLE_TEXT, c, st, 8)
        call table_add_column(t, 'INTERVALLE', TABLE_INT, c, st)
        call table_add_column(t, 'BORNE_INF', TABLE_REAL, c, st)
        call table_add_column(t, 'BORNE_SUP', TABLE_REAL, c, st)
        call table_add_column(t, 'DISTRIBUTION', TABLE_REAL, c, st)
        do k = 1, cmd%count('VOLUMOGRAMME')
            do j = 1, size(indices)
                if (st%failed()) return
                call occurrence_rows(cmd, cmd%occurrence('VOLUMOGRAMME', k), res, &
                    indices(j), mesh, model, t, st)
            end do
        end do
    end subroutine volumogramme_rows

    !> The model: MODELE, else the result's.
    subroutine model_of(cmd, res, model, st)
        type(command_t), intent(in) :: cmd
        class(result_fields_t), target, intent(in) :: res
        type(model_t), pointer, intent(out) :: model
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: p
        model => null()
        if (cmd%has('MODELE')) then
            call cmd%get_concept('MODELE', p, st)
            if (st%failed()) return
            select type (p)
            type is (model_concept_t)
                model => p%model
            class default
                call cmd%error_at('MODELE', 'expected a model (modele), got ' // &
                    p%type_name(), st)
            end select
            return
        end if
        select type (res)
        type is (result_concept_t)
            if (allocated(res%model%element)) model => res%model
        end select
        if (.not. associated(model)) call cmd%error_at('RESULTAT', 'the result knows no ' // &
            'model (made by CREA_RESU): give MODELE', st)
    end subroutine model_of

    !> The element characteristics: the occurrence's CARA_ELEM, the command's, the result's.
    subroutine cara_of(cmd, occ, res, cara, st)
        type(command_t), intent(in) :: cmd
        type(keyword_set_t), intent(in) :: occ
        class(result_fields_t), target, intent(in) :: res
        type(cara_elem_t), pointer, intent(out) :: cara
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: p
        cara => null()
        if (occ%has('CARA_ELEM')) then
            call occ%get_concept('CARA_ELEM', p, st)
        else if (cmd%has('CARA_ELEM')) then
            call cmd%get_concept('CARA_ELEM', p, st)
        else
            select type (res)
            type is (result_concept_t)
                if (allocated(res%cara%thickness)) cara => res%cara
            end select
            return
        end if
        if (st%failed()) return
        select type (p)
        type is (cara_elem_concept_t)
            cara => p%cara
        class default
            call occ%error_at('CARA_ELEM', 'expected element characteristics (cara_elem), ' // &
                'got ' // p%type_name(), st)
        end select
    end subroutine cara_of

    !> The rows of one occurrence at one stored instant.
    subroutine occurrence_rows(cmd, occ, res, index, mesh, model, t, st)
        type(command_t), intent(in) :: cmd
        type(keyword_set_t), intent(in) :: occ
        class(result_fields_t), pointer :: res
        integer, intent(in) :: index
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(cara_elem_t), pointer :: cara
        type(field_t), pointer :: f
        character(len=:), allocatable :: nom_cham, nom_cmp, group, restriction, norme
        real(dp), allocatable :: values(:), weights(:), bounds(:), shares(:)
        real(dp) :: total, threshold
        integer(i4), allocatable :: cells(:)
        integer :: n_interv, k, r, n
        integer(i4) :: g, kc
        logical :: fixed, split
        if (.not. occ%has('NOM_CHAM')) then
            call occ%error_at('', 'give NOM_CHAM, the field of the result (Code_Aster''s ' // &
                'POSTELEM_4)', st)
            return
        end if
        call occ%get_text('NOM_CHAM', nom_cham, st)
        if (st%ok()) call occ%get_text('NOM_CMP', nom_cmp, st)
        if (st%ok()) call occ%get_text('NORME', norme, st)
        if (st%ok()) call cara_of(cmd, occ, res, cara, st)
        if (st%failed()) return
        call result_field_at(res, int(index, i4), nom_cham, f, st)
        if (st%failed()) then
            call relocate_at(occ, 'NOM_CHAM', st)
            return
        end if
        if (f%location /= FIELD_ELGA .and. f%location /= FIELD_ELNO) then
            call occ%error_at('NOM_CHAM', 'VOLUMOGRAMME of a ' // field_location_name(f) // &
                ' field is not built by parasol (ELGA and ELNO fields are): compute ' // &
                nom_cham // '''s _ELGA or _ELNO form with CALC_CHAMP', st, &
                STATUS_NOT_IMPLEMENTED)
            return
        end if
        kc = int(field_component(f, nom_cmp), i4)
        if (kc == 0) then
            call occ%error_at('NOM_CMP', nom_cham // ' has no component ' // nom_cmp // &
                ' (Code_Aster''s CHAMPS_3)', st)
            return
        end if
        ! the cells
        group = '-'
        if (occ%has('GROUP_MA')) then
            call occ%get_text('GROUP_MA', group, st)
            if (st%failed()) return
            g = find_cell_group(mesh, group, st)
            if (st%failed()) then
                call relocate_at(occ, 'GROUP_MA', st)
                return
            end if
            cells = cells_of_group(mesh, g)
        else
            cells = [(g, g=1_i4, mesh%n_cells)]
        end if
        restriction = '-'
        if (occ%has('TYPE_MAILLE')) then
            call occ%get_text('TYPE_MAILLE', restriction, st)
            if (st%failed()) return
            cells = pack(cells, CELL_TYPE_DIM(mesh%cell_type(cells)) == &
                         merge(2_i4, 3_i4, restriction == '2D'))
            if (size(cells) == 0) then
                call occ%error_at('TYPE_MAILLE', 'no cell of the occurrence is ' // &
                    restriction // ' (Code_Aster''s PREPOST2_6)', st)
                return
            end if
        end if
        ! the intervals
        fixed = occ%has('BORNES')
        split = occ%has('SEUIL')
        threshold = 0.0_dp
        if (split) then
            if (fixed) then
                call occ%error_at('SEUIL', 'SEUIL with BORNES is not built by parasol: ' // &
                    'give one of them', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
            call occ%get_real('SEUIL', threshold, st)
            n_interv = 2
        else
            call occ%get_int('NB_INTERV', n_interv, st)
            if (st%ok() .and. (n_interv < 1 .or. n_interv > MAX_INTERVALS)) &
                call occ%error_at('NB_INTERV', 'NB_INTERV is a number of intervals: 1 .. ' // &
                    to_text(int(MAX_INTERVALS, i4)), st)
        end if
        allocate (bounds(2))
        bounds = 0.0_dp
        if (st%ok() .and. fixed) call occ%get_reals('BORNES', bounds, st)
        if (st%failed()) return
        if (fixed .and. .not. bounds(1) < bounds(2)) then
            call occ%error_at('BORNES', 'BORNES are the range (low, high) of the values: ' // &
                'low < high', st)
            return
        end if
        if (any(abs([bounds, threshold]) > VALUE_LIMIT)) then
            call occ%error_at(merge('BORNES', 'SEUIL ', fixed), 'a bound beyond ' // &
                '1E+300 is not a value of a field', st)
            return
        end if
        call point_values(occ, mesh, model, cara, f, cells, kc, fixed, bounds, values, &
            weights, st)
        if (st%failed()) return
        call distribute(values, weights, n_interv, fixed, bounds, split, threshold, &
            norme == 'RELATIF', shares, total)
        if (.not. (abs(total) <= huge(1.0_dp))) then
            call occ%error_at('NOM_CMP', 'the weights of the points sum beyond double ' // &
                'precision', st, STATUS_MODEL_ERROR)
            return
        end if
        n = t%n_rows
        call table_add_rows(t, n_interv)
        do k = 1, n_interv
            r = n + k
            call table_set_text(t, 1, r, res%name, st)
            call table_set_text(t, 2, r, nom_cham, st)
            call table_set_int(t, 3, r, int(res%nume_ordre(index), i8), st)
            call table_set_real(t, 4, r, res%inst(index), st)
            call table_set_text(t, 5, r, nom_cmp, st)
            call table_set_text(t, 6, r, group, st)
            call table_set_text(t, 7, r, restriction, st)
            call table_set_int(t, 8, r, int(k, i8), st)
            call table_set_real(t, 9, r, shares(3 * k - 2), st)
            call table_set_real(t, 10, r, shares(3 * k - 1), st)
            call table_set_real(t, 11, r, shares(3 * k), st)
            if (st%failed()) return
        end do
    end subroutine occurrence_rows

    !> The values of component kc at the points of the cells, with their weights (module
    !> header); with BORNES only those inside them.
    subroutine point_values(occ, mesh, model, cara, f, cells, kc, fixed, bounds, values, &
                            weights, st)
        type(keyword_set_t), intent(in) :: occ
        type(mesh_t), intent(in) :: mesh
        type(model_t), intent(in) :: model
        type(cara_elem_t), pointer, intent(in) :: cara
        type(field_t), intent(in) :: f
        integer(i4), intent(in) :: cells(:), kc
        logical, intent(in) :: fixed
        real(dp), intent(in) :: bounds(2)
        real(dp), allocatable, intent(out) :: values(:), weights(:)
        type(status_t), intent(inout) :: st
        type(gauss_rule_t) :: rule
        real(dp), allocatable :: w(:)
        real(dp) :: x(3, MAX_CELL_NODES), v, measure, layer
        integer(i8) :: pos
        integer :: m
        integer(i4) :: c, p, q, nn, np, nq, layers
        m = 0
        allocate (values(0), weights(0))
        do c = 1, size(cells)
            if (cells(c) > f%n_cells) cycle
            np = f%n_points(cells(c))
            if (np == 0) cycle
            nq = f%n_subpoints(cells(c))
            nn = CELL_TYPE_NODES(mesh%cell_type(cells(c)))
            x(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(cells(c)): &
                mesh%cell_ptr(cells(c)) + nn - 1))
            ! the factor of each sub-point: h/n times Simpson's weight on a layered plate
            layers = 1
            layer = 1.0_dp
            if (nq > 1) then
                if (.not. associated(cara) .or. cells(c) > size(model%element)) then
                    call no_layers()
                    return
                end if
                if (.not. is_plate(model%element(cells(c))) .or. &
                    cells(c) > size(cara%thickness)) then
                    call no_layers()
                    return
                end if
                layers = max(1_i4, cara%coque_layers(cells(c)))
                if (nq /= 3 * layers) then
                    call no_layers()
                    return
                end if
                layer = cara%thickness(cells(c)) / layers
            end if
            if (f%location == FIELD_ELGA) then
                if (cells(c) > size(model%element)) then
                    call occ%error_at('NOM_CHAM', 'cell ' // to_text(cells(c)) // &
                        ' carries the field but is not in the model', st, STATUS_MODEL_ERROR)
                    return
                end if
                call element_points(model%element(cells(c)), mesh%cell_type(cells(c)), np, &
                    rule, st)
                if (st%failed()) then
                    call relocate_at(occ, 'NOM_CHAM', st)
                    return
                end if
                w = point_weights(rule, x(:, 1:nn))
            else
                measure = cell_geometric_measure(mesh%cell_type(cells(c)), x(:, 1:nn))
                w = [(measure / np, p=1_i4, np)]
            end if
            do p = 1, np
                do q = 1, nq
                    pos = field_position(f, cells(c), p, q, kc)
                    if (pos == 0) cycle
                    v = f%values(pos)
                    if (abs(v) > VALUE_LIMIT) then
                        call occ%error_at('NOM_CMP', 'a value of the component reaches ' // &
                            'beyond 1E+300 (cell ' // to_text(cells(c)) // '): its ' // &
                            'intervals are not finite doubles', st, STATUS_MODEL_ERROR)
                        return
                    end if
                    if (fixed .and. .not. (v >= bounds(1) .and. v <= bounds(2))) cycle
                    m = m + 1
                    if (m > size(values)) call grow()
                    values(m) = v
                    weights(m) = w(p)
                    if (nq > 1) weights(m) = w(p) * layer * LEVEL_WEIGHTS(mod(q - 1, 3) + 1)
                end do
            end do
        end do
        values = values(1:m)
        weights = weights(1:m)
        if (m == 0 .and. .not. fixed) call occ%error_at('NOM_CMP', 'no cell of the ' // &
            'occurrence holds a value of the component: there are no intervals', st, &
            STATUS_MODEL_ERROR)
    contains
        subroutine no_layers()
            call occ%error_at('CARA_ELEM', 'the field has sub-points on cell ' // &
                to_text(cells(c)) // ': their weights are those of a plate''s layers ' // &
                '(COQUE EPAIS, COQUE_NCOU of CARA_ELEM), which give 3 per layer', st, &
                STATUS_MODEL_ERROR)
        end subroutine no_layers

        subroutine grow()
            real(dp), allocatable :: more(:)
            allocate (more(max(64, 2 * size(values))), source=0.0_dp)
            more(1:size(values)) = values
            call move_alloc(more, values)
            allocate (more(size(values)), source=0.0_dp)
            more(1:size(weights)) = weights
            call move_alloc(more, weights)
        end subroutine grow
    end subroutine point_values

    !> Gauss weight times the jacobian of the cell's map at each point of the rule (a line:
    !> the length of the tangent; a surface in space: sqrt of the metric's determinant, as
    !> te0488's sumetr; POI1: 1).
    function point_weights(rule, x) result(w)
        type(gauss_rule_t), intent(in) :: rule
        real(dp), intent(in) :: x(:, :)
        real(dp) :: w(rule%n)
        real(dp) :: n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES), a(3), b(3), jac
        integer(i4) :: g, nn
        nn = CELL_TYPE_NODES(rule%cell_type)
        do g = 1, rule%n
            call cell_shape(rule%cell_type, rule%xi(1, g), rule%xi(2, g), n(1:nn), dn(:, 1:nn))
            a = matmul(x(:, 1:nn), dn(1, 1:nn))
            b = matmul(x(:, 1:nn), dn(2, 1:nn))
            select case (CELL_TYPE_DIM(rule%cell_type))
            case (0)
                jac = 1.0_dp
            case (1)
                jac = norm2(a)
            case default
                jac = sqrt(max(0.0_dp, dot_product(a, a) * dot_product(b, b) - &
                                       dot_product(a, b)**2))
            end select
            w(g) = jac * rule%w(g)
        end do
    end function point_weights

    !> pebpct: shares(3 k - 2 : 3 k) = lower bound, upper bound, distribution of interval k.
    subroutine distribute(values, weights, n_interv, fixed, bounds, split, threshold, &
                          relative, shares, total)
        real(dp), intent(in) :: values(:), weights(:), bounds(2), threshold
        integer, intent(in) :: n_interv
        logical, intent(in) :: fixed, split, relative
        real(dp), allocatable, intent(out) :: shares(:)
        real(dp), intent(out) :: total
        real(dp) :: low, high, step, p0
        integer :: i, j
        allocate (shares(3 * n_interv), source=0.0_dp)
        total = sum(weights)
        if (fixed) then
            low = bounds(1)
            high = bounds(2)
        else
            low = minval(values)
            high = maxval(values)
            if (abs(low - high) <= tiny(1.0_dp)) then
                shares(3::3) = 100.0_dp / n_interv
                return
            end if
        end if
        if (split) then
            shares(1:6) = [low, threshold, 0.0_dp, threshold, high, 0.0_dp]
        else
            step = (high - low) / n_interv
            p0 = low
            do i = 1, n_interv
                shares(3 * i - 2) = p0
                shares(3 * i - 1) = p0 + step
                p0 = p0 + step
            end do
        end if
        do j = 1, size(values)
            if (values(j) < shares(2)) shares(3) = shares(3) + weights(j)
        end do
        ! the middle intervals [low, high) follow one another (each upper bound is the next
        ! lower one): a value's is found by bisection over the lower bounds
        if (n_interv > 2) then
            do j = 1, size(values)
                i = last_at_or_below(values(j))
                if (i >= 2 .and. i <= n_interv - 1) then
                    if (values(j) < shares(3 * i - 1)) shares(3 * i) = shares(3 * i) + weights(j)
                end if
            end do
        end if
        do j = 1, size(values)
            if (values(j) >= shares(3 * n_interv - 2)) &
                shares(3 * n_interv) = shares(3 * n_interv) + weights(j)
        end do
        if (relative) then
            if (total > 0.0_dp) shares(3::3) = 100.0_dp * shares(3::3) / total
        else
            shares(3::3) = 100.0_dp * shares(3::3) / 100.0_dp
        end if
    contains
        !> The last interval whose lower bound is at most v (0: none).
        pure integer function last_at_or_below(v) result(k)
            real(dp), intent(in) :: v
            integer :: a, b, mid
            a = 0
            b = n_interv
            do while (a < b)
                mid = (a + b + 1) / 2
                if (shares(3 * mid - 2) <= v) then
                    a = mid
                else
                    b = mid - 1
                end if
            end do
            k = a
        end function last_at_or_below
    end subroutine distribute

end module post_elem_volumogramme
