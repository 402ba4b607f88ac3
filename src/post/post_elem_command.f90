!> POST_ELEM (U4.81.22) MASS_INER: the mass, centre of gravity and inertia tensor of parts
!> of a model, as Code_Aster's pemain / pemica tabulate them, from the elements parasol has:
!>  - plates (DKT, DKQ): the mid-surface of thickness h (CARA_ELEM COQUE EPAIS) and density
!>    RHO: m = RHO h A; about the cell's centre the inertia of the surface plus the
!>    thickness term RHO h^3/12 A (I - n n^T) (n the cell's normal), Code_Aster's dxiner;
!>  - plane solids (D_PLAN, C_PLAN): per unit thickness, m = RHO A, z = 0 (te0285);
!>  - cells without mass (discretes: parasol's have none; load edges) are left out.
!> The integrals are Gauss rules on the reference element (3 x 3 on quadrangles; triangles
!> mapped onto the square, Duffy), exact for straight-sided cells.
!> Each occurrence gives rows: TOUT (LIEU the mesh's name, ENTITE TOUT), each GROUP_MA
!> (LIEU the group, ENTITE GROUP_MA) and their union when there are several
!> (UNION_GROUP_MA), each MAILLE (LIEU the cell). Columns: LIEU, ENTITE, MASSE, CDG_X..Z,
!> IX_G, IY_G, IZ_G (moments about the centre of gravity G), IXY_G, IXZ_G, IYZ_G (products
!> +int (x-xg)(y-yg) dm), IX_PRIN_G <= IY_PRIN_G <= IZ_PRIN_G (principal moments,
!> increasing, as Code_Aster's jacobi sorts them), ALPHA, BETA, GAMMA (nautical angles in
!> degrees of the principal frame: its x axis along the first principal axis, its y axis
!> along the second; each axis signed so that its largest component is positive); with
!> ORIG_INER the point P (X_P, Y_P, Z_P) and the moments and products about P (IX_P ..).
!> ENER_POT and TRAV_EXT are post_elem_energy's, MINMAX post_elem_minmax's. The other options, and MASS_INER on a RESULTAT or
!> CHAM_GD (GEOMETRIE 'DEFORMEE'), are located errors saying they are not built.
module post_elem_command
    use kinds, only: dp, i4
    use strings, only: string_t, to_text
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group, find_cell, cell_name
    use mesh_cell_shapes, only: cell_shape, CELL_TYPE_NODES, CELL_TRIA3, CELL_TRIA6, &
        MAX_CELL_NODES
    use model_types, only: is_plate, is_plane_solid
    use model_concept, only: model_concept_t
    use material_concept, only: material_field_concept_t
    use cara_elem_concept, only: cara_elem_concept_t
    use element_quadrature, only: gauss_quad
    use table_concept, only: table_t, table_init, table_add_column, table_add_rows, &
        table_set_real, table_set_text, TABLE_REAL, TABLE_TEXT
    use table_keywords, only: relocate_at
    use post_elem_minmax, only: minmax_rows
    use post_elem_volumogramme, only: volumogramme_rows
    use post_elem_energy, only: ener_pot_rows, trav_ext_rows, mesh_concept_name
    implicit none
    private
    public :: run_post_elem

    !> The options of Code_Aster's POST_ELEM other than MASS_INER (not built).
    character(len=*), parameter :: OTHER_OPTIONS = 'ENER_CIN ' // &
        'WEIBULL RICE_TRACEY CARA_GEOM CHAR_LIMITE NORME CARA_POUTRE INDIC_ENER ' // &
        'INDIC_SEUIL AIRE_INTERNE ENER_ELAS ENER_ELTR ENER_TOTALE ENER_DISS ' // &
        'INTEGRALE'
    character(len=*), parameter :: COLUMNS = 'MASSE CDG_X CDG_Y CDG_Z IX_G IY_G IZ_G ' // &
        'IXY_G IXZ_G IYZ_G IX_PRIN_G IY_PRIN_G IZ_PRIN_G ALPHA BETA GAMMA'
    character(len=*), parameter :: POINT_COLUMNS = 'X_P Y_P Z_P IX_P IY_P IZ_P IXY_P ' // &
        'IXZ_P IYZ_P'

    !> Relative area (to the square of a cell's size) under which a cell is degenerate.
    real(dp), parameter :: DEGENERATE = 1.0e-12_dp

    !> Mass properties of one cell: mass, centre, inertia tensor about the centre.
    type :: cell_mass_t
        real(dp) :: m = 0.0_dp
        real(dp) :: g(3) = 0.0_dp
        real(dp) :: j(3, 3) = 0.0_dp
    end type cell_mass_t

    !> The model, materials and characteristics MASS_INER reads.
    type :: inputs_t
        type(model_concept_t), pointer :: mo => null()
        type(material_field_concept_t), pointer :: mat => null()
        type(cara_elem_concept_t), pointer :: cara => null()
        character(len=:), allocatable :: mesh_name
    end type inputs_t

contains

    !> Handler of POST_ELEM.
    subroutine run_post_elem(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        type(table_t), allocatable :: t
        type(inputs_t) :: in
        type(cell_mass_t), allocatable :: cells(:)
        type(keyword_set_t) :: occ
        character(len=:), allocatable :: key
        logical :: with_point
        integer :: k, a, b, c
        a = 1
        do while (a <= len(OTHER_OPTIONS))
            b = index(OTHER_OPTIONS(a:) // ' ', ' ') + a - 2
            if (cmd%count(OTHER_OPTIONS(a:b)) > 0) then
                call cmd%error_at(OTHER_OPTIONS(a:b), 'POST_ELEM ' // OTHER_OPTIONS(a:b) // &
                    ' is not built by parasol: MASS_INER, ENER_POT, TRAV_EXT, MINMAX and ' // &
                    'VOLUMOGRAMME are', &
                    st, &
                    STATUS_NOT_IMPLEMENTED)
                return
            end if
            a = b + 2
        end do
        if (cmd%count('ENER_POT') > 0 .or. cmd%count('TRAV_EXT') > 0 .or. &
            cmd%count('MINMAX') > 0 .or. cmd%count('VOLUMOGRAMME') > 0) then
            allocate (t)
            call table_init(t)
            if (cmd%count('ENER_POT') > 0) then
                call ener_pot_rows(ctx, cmd, t, st)
            else if (cmd%count('TRAV_EXT') > 0) then
                call trav_ext_rows(cmd, t, st)
            else if (cmd%count('MINMAX') > 0) then
                call minmax_rows(cmd, t, st)
            else
                call volumogramme_rows(cmd, t, st)
            end if
            if (st%failed()) return
            if (cmd%has('TITRE')) call cmd%get_texts('TITRE', t%title, st)
            if (st%failed()) return
            call ctx%write_mess('    POST_ELEM: ' // to_text(int(t%n_rows, i4)) // ' rows')
            call move_alloc(t, result)
            return
        end if
        if (cmd%count('MASS_INER') == 0) then
            call cmd%error_at('MASS_INER', 'give the quantity to compute (MASS_INER or ' // &
                'ENER_POT)', st)
            return
        end if
        do k = 1, 2
            key = 'CHAM_GD'
            if (k == 1) key = 'RESULTAT'
            if (cmd%has(key)) then
                call cmd%error_at(key, 'MASS_INER on the fields of ' // key // &
                    ' (GEOMETRIE, instants) is not built by parasol: give MODELE, ' // &
                    'CHAM_MATER and CARA_ELEM', st, STATUS_NOT_IMPLEMENTED)
                return
            end if
        end do
        call read_inputs(ctx, cmd, in, st)
        if (st%failed()) return
        call cell_masses(cmd, in, cells, st)
        if (st%failed()) return
        with_point = .false.
        do k = 1, cmd%count('MASS_INER')
            occ = cmd%occurrence('MASS_INER', k)
            if (occ%has('ORIG_INER')) with_point = .true.
        end do
        allocate (t)
        call table_init(t)
        call table_add_column(t, 'LIEU', TABLE_TEXT, c, st, 24)
        call table_add_column(t, 'ENTITE', TABLE_TEXT, c, st, 8)
        call add_columns(t, COLUMNS, st)
        if (with_point) call add_columns(t, POINT_COLUMNS, st)
        if (st%failed()) return
        do k = 1, cmd%count('MASS_INER')
            call occurrence_rows(cmd%occurrence('MASS_INER', k), in, cells, t, st)
            if (st%failed()) return
        end do
        if (cmd%has('TITRE')) then
            call cmd%get_texts('TITRE', t%title, st)
            if (st%failed()) return
        end if
        call ctx%write_mess('    POST_ELEM MASS_INER: ' // to_text(int(t%n_rows, i4)) // ' rows')
        call move_alloc(t, result)
    end subroutine run_post_elem

    subroutine add_columns(t, names, st)
        type(table_t), intent(inout) :: t
        character(len=*), intent(in) :: names
        type(status_t), intent(inout) :: st
        integer :: a, b, c
        a = 1
        do while (a <= len(names) .and. st%ok())
            b = index(names(a:) // ' ', ' ') + a - 2
            call table_add_column(t, names(a:b), TABLE_REAL, c, st)
            a = b + 2
        end do
    end subroutine add_columns

    !> MODELE, CHAM_MATER, CARA_ELEM and the mesh's name (LIEU of TOUT).
    subroutine read_inputs(ctx, cmd, in, st)
        type(run_context_t), intent(in) :: ctx
        type(command_t), intent(in) :: cmd
        type(inputs_t), intent(out) :: in
        type(status_t), intent(inout) :: st
        class(concept_t), pointer :: p
        if (.not. cmd%has('MODELE')) then
            call cmd%error_at('MASS_INER', 'MASS_INER needs MODELE (the elements whose ' // &
                'mass is summed)', st)
            return
        end if
        call cmd%get_concept('MODELE', p, st)
        if (st%failed()) return
        select type (p)
        type is (model_concept_t)
            in%mo => p
        class default
            call cmd%error_at('MODELE', 'expected a model (modele), got ' // p%type_name(), st)
            return
        end select
        if (cmd%has('CHAM_MATER')) then
            call cmd%get_concept('CHAM_MATER', p, st)
            if (st%failed()) return
            select type (p)
            type is (material_field_concept_t)
                in%mat => p
            class default
                call cmd%error_at('CHAM_MATER', 'expected a material field (cham_mater), ' // &
                    'got ' // p%type_name(), st)
                return
            end select
        end if
        if (cmd%has('CARA_ELEM')) then
            call cmd%get_concept('CARA_ELEM', p, st)
            if (st%failed()) return
            select type (p)
            type is (cara_elem_concept_t)
                in%cara => p
            class default
                call cmd%error_at('CARA_ELEM', 'expected element characteristics ' // &
                    '(cara_elem), got ' // p%type_name(), st)
                return
            end select
        end if
        in%mesh_name = mesh_concept_name(ctx, in%mo%mesh)
    end subroutine read_inputs

    !> The mass properties of every cell with mass (plates, plane solids).
    subroutine cell_masses(cmd, in, cells, st)
        type(command_t), intent(in) :: cmd
        type(inputs_t), intent(in) :: in
        type(cell_mass_t), allocatable, intent(out) :: cells(:)
        type(status_t), intent(inout) :: st
        type(mesh_t), pointer :: mesh
        integer(i4) :: c, kind, m
        real(dp) :: rho, h
        character(len=:), allocatable :: key
        logical :: ok
        mesh => in%mo%mesh
        allocate (cells(mesh%n_cells))
        do c = 1, mesh%n_cells
            kind = in%mo%model%element(c)
            if (.not. (is_plate(kind) .or. is_plane_solid(kind))) cycle
            m = 0
            if (associated(in%mat)) m = in%mat%field%cell_material(c)
            if (m == 0) then
                key = 'MODELE'
                if (associated(in%mat)) key = 'CHAM_MATER'
                call cmd%error_at(key, 'cell ' // cell_name(mesh, c) // ' has no material: MASS_INER needs ' // &
                    'the density RHO of ELAS (give CHAM_MATER)', st, STATUS_MODEL_ERROR)
                return
            end if
            associate (mat => in%mat%field%materials(m))
                if (.not. (mat%has_elas .and. mat%elas%has_rho)) then
                    call cmd%error_at('CHAM_MATER', 'material ' // mat%name // ' of cell ' // &
                        cell_name(mesh, c) // ' gives no density: MASS_INER needs ELAS ' // &
                        'RHO', st, STATUS_MODEL_ERROR)
                    return
                end if
                rho = mat%elas%rho
            end associate
            h = 1.0_dp
            if (is_plate(kind)) then
                if (.not. associated(in%cara)) then
                    call cmd%error_at('MODELE', 'the plate cell ' // cell_name(mesh, c) // &
                        ' needs its thickness: give CARA_ELEM', st, STATUS_MODEL_ERROR)
                    return
                end if
                if (.not. in%cara%cara%has_coque(c)) then
                    call cmd%error_at('CARA_ELEM', 'the plate cell ' // cell_name(mesh, c) // &
                        ' has no COQUE thickness in the CARA_ELEM', st, STATUS_MODEL_ERROR)
                    return
                end if
                h = in%cara%cara%thickness(c)
            end if
            call surface_cell(mesh, c, rho * h, cells(c), ok)
            if (ok .and. is_plate(kind)) call add_thickness_term(mesh, c, h, cells(c), ok)
            if (.not. ok) then
                call cmd%error_at('MODELE', 'cell ' // cell_name(mesh, c) // ' is ' // &
                    'degenerate (no area or no normal): its mass and inertia are undefined', &
                    st, STATUS_MODEL_ERROR)
                return
            end if
        end do
    end subroutine cell_masses

    !> Mass, centre and inertia about the centre of a surface cell of mass `areal` per
    !> unit area (the integrals of the module header).
    !>  ok : false when the cell has no area (degenerate)
    subroutine surface_cell(mesh, c, areal, cm, ok)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: areal
        type(cell_mass_t), intent(out) :: cm
        logical, intent(out) :: ok
        real(dp) :: x(3, MAX_CELL_NODES), n(MAX_CELL_NODES), dn(2, MAX_CELL_NODES)
        real(dp) :: q(2, 9), w(9), p(3), t1(3), t2(3), da, area, s(3), ss(3, 3), xi, eta
        real(dp) :: second(3, 3)
        integer(i4) :: ctype, nn, k, i
        logical :: tria
        ctype = mesh%cell_type(c)
        nn = CELL_TYPE_NODES(ctype)
        x(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c) + nn - 1))
        tria = ctype == CELL_TRIA3 .or. ctype == CELL_TRIA6
        call gauss_quad(3_i4, q, w)
        area = 0.0_dp
        s = 0.0_dp
        ss = 0.0_dp
        do k = 1, 9
            xi = q(1, k)
            eta = q(2, k)
            da = w(k)
            if (tria) then
                ! Duffy: u = (1 + xi)/2, v = (1 - u)(1 + eta)/2, dA_ref = (1 - u)/4
                xi = (1.0_dp + q(1, k)) / 2.0_dp
                eta = (1.0_dp - xi) * (1.0_dp + q(2, k)) / 2.0_dp
                da = w(k) * (1.0_dp - xi) / 4.0_dp
            end if
            call cell_shape(ctype, xi, eta, n, dn)
            p = matmul(x(:, 1:nn), n(1:nn))
            t1 = matmul(x(:, 1:nn), dn(1, 1:nn))
            t2 = matmul(x(:, 1:nn), dn(2, 1:nn))
            da = da * norm2(cross(t1, t2))
            area = area + da
            s = s + da * p
            do i = 1, 3
                ss(:, i) = ss(:, i) + da * p * p(i)
            end do
        end do
        ! degenerate: an area below 1e-12 of the square of the cell's size (a flat cell)
        ok = area > DEGENERATE * (maxval(maxval(x(:, 1:nn), dim=2) - &
                                         minval(x(:, 1:nn), dim=2)))**2
        if (.not. ok) return
        cm%m = areal * area
        cm%g = s / area
        do i = 1, 3
            second(:, i) = areal * (ss(:, i) - area * cm%g * cm%g(i))
        end do
        cm%j = -second
        do i = 1, 3
            cm%j(i, i) = cm%j(i, i) + (second(1, 1) + second(2, 2) + second(3, 3))
        end do
    end subroutine surface_cell

    !> The plate's thickness: RHO h^3/12 A (I - n n^T) about the centre (dxiner).
    !>  ok : false when the cell has no normal
    subroutine add_thickness_term(mesh, c, h, cm, ok)
        type(mesh_t), intent(in) :: mesh
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: h
        type(cell_mass_t), intent(inout) :: cm
        logical, intent(out) :: ok
        real(dp) :: nrm(3), x(3, 4), coef
        integer(i4) :: nn, i
        nn = min(4_i4, mesh%cell_ptr(c + 1) - mesh%cell_ptr(c))
        x(:, 1:nn) = mesh%coords(:, mesh%cell_nodes(mesh%cell_ptr(c):mesh%cell_ptr(c) + nn - 1))
        if (nn == 4) then
            nrm = cross(x(:, 3) - x(:, 1), x(:, 4) - x(:, 2))
        else
            nrm = cross(x(:, 2) - x(:, 1), x(:, 3) - x(:, 1))
        end if
        ok = norm2(nrm) > 0.0_dp
        if (.not. ok) return
        nrm = nrm / norm2(nrm)
        coef = cm%m * h * h / 12.0_dp      ! RHO h A * h^2/12
        do i = 1, 3
            cm%j(:, i) = cm%j(:, i) - coef * nrm * nrm(i)
            cm%j(i, i) = cm%j(i, i) + coef
        end do
    end subroutine add_thickness_term

    pure function cross(a, b) result(v)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: v(3)
        v = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    ! ---- the rows ----------------------------------------------------------------------

    !> The rows of one MASS_INER occurrence (module header).
    subroutine occurrence_rows(occ, in, cells, t, st)
        type(keyword_set_t), intent(in) :: occ
        type(inputs_t), intent(in) :: in
        type(cell_mass_t), intent(in) :: cells(:)
        type(table_t), intent(inout) :: t
        type(status_t), intent(inout) :: st
        type(mesh_t), pointer :: mesh
        type(string_t), allocatable :: names(:)
        logical, allocatable :: mask(:), union(:)
        real(dp), allocatable :: orig(:)
        logical :: has_point
        integer(i4) :: g, cell
        integer :: k
        mesh => in%mo%mesh
        has_point = occ%has('ORIG_INER')
        allocate (orig(3), source=0.0_dp)
        if (has_point) call occ%get_reals('ORIG_INER', orig, st)
        if (st%failed()) return
        if (occ%has('TOUT')) then
            allocate (mask(mesh%n_cells), source=.true.)
            call add_row(in%mesh_name, 'TOUT', mask)
        end if
        if (occ%has('GROUP_MA')) then
            call occ%get_texts('GROUP_MA', names, st)
            if (st%failed()) return
            allocate (union(mesh%n_cells), source=.false.)
            do k = 1, size(names)
                g = find_cell_group(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'GROUP_MA', st)
                    return
                end if
                if (allocated(mask)) deallocate (mask)
                allocate (mask(mesh%n_cells), source=.false.)
                mask(cells_of_group(mesh, g)) = .true.
                union = union .or. mask
                call add_row(names(k)%s, 'GROUP_MA', mask)
            end do
            if (size(names) > 1) call add_row('UNION_GROUP_MA', 'GROUP_MA', union)
        end if
        if (occ%has('MAILLE')) then
            call occ%get_texts('MAILLE', names, st)
            if (st%failed()) return
            do k = 1, size(names)
                cell = find_cell(mesh, names(k)%s, st)
                if (st%failed()) then
                    call relocate_at(occ, 'MAILLE', st)
                    return
                end if
                if (allocated(mask)) deallocate (mask)
                allocate (mask(mesh%n_cells), source=.false.)
                mask(cell) = .true.
                call add_row(names(k)%s, 'MAILLE', mask)
            end do
        end if
    contains
        subroutine add_row(lieu, entite, chosen)
            character(len=*), intent(in) :: lieu, entite
            logical, intent(in) :: chosen(:)
            real(dp) :: v(16), vp(9)
            integer :: r, j
            if (st%failed()) return
            call part_properties(cells, chosen, orig, v, vp)
            call table_add_rows(t, 1)
            r = t%n_rows
            call table_set_text(t, 1, r, lieu, st)
            call table_set_text(t, 2, r, entite, st)
            do j = 1, 16
                call table_set_real(t, 2 + j, r, v(j), st)
            end do
            if (has_point) then
                do j = 1, 9
                    call table_set_real(t, 18 + j, r, vp(j), st)
                end do
            end if
        end subroutine add_row
    end subroutine occurrence_rows

    !> The sixteen values of a part (MASSE .. GAMMA) and the nine about the point orig.
    subroutine part_properties(cells, chosen, orig, v, vp)
        type(cell_mass_t), intent(in) :: cells(:)
        logical, intent(in) :: chosen(:)
        real(dp), intent(in) :: orig(3)
        real(dp), intent(out) :: v(16), vp(9)
        real(dp) :: mass, g(3), jg(3, 3), jp(3, 3), d(3), a(3, 3), w(3)
        real(dp) :: e1(3), e2(3), y2, z2, alpha, beta, gamma
        integer :: c, i
        mass = 0.0_dp
        g = 0.0_dp
        do c = 1, size(cells)
            if (.not. chosen(c) .or. cells(c)%m <= 0.0_dp) cycle
            mass = mass + cells(c)%m
            g = g + cells(c)%m * cells(c)%g
        end do
        v = 0.0_dp
        vp = 0.0_dp
        if (mass > 0.0_dp) g = g / mass
        jg = 0.0_dp
        do c = 1, size(cells)
            if (.not. chosen(c) .or. cells(c)%m <= 0.0_dp) cycle
            d = cells(c)%g - g
            jg = jg + cells(c)%j + cells(c)%m * shift(d)
        end do
        v(1) = mass
        v(2:4) = g
        ! + 0: a product that is zero is written 0, not -0
        v(5:10) = [jg(1, 1), jg(2, 2), jg(3, 3), -jg(1, 2), -jg(1, 3), -jg(2, 3)] + 0.0_dp
        if (any(abs(v(5:10)) >= 1.0e-12_dp)) then       ! Code_Aster's pemica threshold
            call symmetric_eigen(jg, w, a)
            block
                v(11:13) = w
                do i = 1, 3
                    a(:, i) = a(:, i) * sign(1.0_dp, a(maxloc(abs(a(:, i)), dim=1), i))
                end do
                e1 = a(:, 1)
                alpha = atan2(e1(2), e1(1))
                beta = -atan2(e1(3), hypot(e1(1), e1(2)))
                e2 = a(:, 2)
                ! the second axis in the frame turned by (alpha, beta): its y and z
                y2 = -sin(alpha) * e2(1) + cos(alpha) * e2(2)
                z2 = sin(beta) * cos(alpha) * e2(1) + sin(beta) * sin(alpha) * e2(2) + &
                    cos(beta) * e2(3)
                gamma = 0.0_dp
                if (abs(y2) > 0.0_dp .or. abs(z2) > 0.0_dp) gamma = atan2(z2, y2)
                v(14:16) = [alpha, beta, gamma] * (45.0_dp / atan(1.0_dp)) + 0.0_dp
            end block
        end if
        vp(1:3) = orig
        jp = jg + mass * shift(g - orig)
        vp(4:9) = [jp(1, 1), jp(2, 2), jp(3, 3), -jp(1, 2), -jp(1, 3), -jp(2, 3)] + 0.0_dp
    end subroutine part_properties

    !> Eigenvalues (increasing) and unit eigenvectors (columns) of a symmetric 3 x 3
    !> matrix by cyclic Jacobi rotations (Golub & Van Loan, 8.5), to the last bits.
    pure subroutine symmetric_eigen(s, w, v)
        real(dp), intent(in) :: s(3, 3)
        real(dp), intent(out) :: w(3), v(3, 3)
        real(dp) :: a(3, 3), theta, t, co, si, tmp(3), off, scale
        integer :: sweep, p, q, i, j, order(3)
        a = s
        v = 0.0_dp
        do i = 1, 3
            v(i, i) = 1.0_dp
        end do
        scale = max(maxval(abs(a)), tiny(1.0_dp))
        do sweep = 1, 50
            off = abs(a(1, 2)) + abs(a(1, 3)) + abs(a(2, 3))
            if (off <= 1.0e-17_dp * scale) exit
            do p = 1, 2
                do q = p + 1, 3
                    if (abs(a(p, q)) <= 1.0e-300_dp) cycle
                    theta = (a(q, q) - a(p, p)) / (2.0_dp * a(p, q))
                    t = sign(1.0_dp, theta) / (abs(theta) + sqrt(theta * theta + 1.0_dp))
                    co = 1.0_dp / sqrt(t * t + 1.0_dp)
                    si = t * co
                    do j = 1, 3        ! a <- J^T a J
                        tmp(1) = co * a(p, j) - si * a(q, j)
                        a(q, j) = si * a(p, j) + co * a(q, j)
                        a(p, j) = tmp(1)
                    end do
                    do j = 1, 3
                        tmp(1) = co * a(j, p) - si * a(j, q)
                        a(j, q) = si * a(j, p) + co * a(j, q)
                        a(j, p) = tmp(1)
                    end do
                    do j = 1, 3
                        tmp(1) = co * v(j, p) - si * v(j, q)
                        v(j, q) = si * v(j, p) + co * v(j, q)
                        v(j, p) = tmp(1)
                    end do
                end do
            end do
        end do
        w = [a(1, 1), a(2, 2), a(3, 3)]
        order = [1, 2, 3]
        do i = 1, 2                 ! increasing, stable
            do j = 1, 3 - i
                if (w(order(j)) > w(order(j + 1))) order([j, j + 1]) = order([j + 1, j])
            end do
        end do
        w = w(order)
        v = v(:, order)
    end subroutine symmetric_eigen

    !> Huygens: the inertia tensor of a unit mass at offset d, |d|^2 I - d d^T.
    pure function shift(d) result(s)
        real(dp), intent(in) :: d(3)
        real(dp) :: s(3, 3)
        integer :: i
        do i = 1, 3
            s(:, i) = -d * d(i)
            s(i, i) = s(i, i) + dot_product(d, d)
        end do
    end function shift

end module post_elem_command
