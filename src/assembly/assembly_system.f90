!> Global system of a static analysis: the structure (mesh, model, materials, element
!> characteristics, DOF numbering, DIS_CHOC cells), the numbering of the free equations
!> (imposed ones are eliminated, RCMK/METIS/SANS renumbering of the nodes), the skyline
!> matrix pattern, assembly of the stiffness (springs at their current DIS_CHOC status or
!> "elastic": all closed and bilateral) and the internal forces f_int(u) with the spring
!> statuses. Vectors u, f_int, f_ext are indexed by the ORIGINAL equations of
!> structure%dofs; the matrix is indexed by the free equations map%free_eq(eq).
module assembly_system
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED
    use strings, only: to_text, string_t
    use mesh_types, only: mesh_t, cell_label, CELL_POI1, MAX_CELL_NODES
    use model_types, only: model_t, is_plate, is_plane_solid, is_load_edge, is_discrete, &
        is_discrete_2d, is_plane_strain, is_discrete_rotational, ELEM_NONE, ELEM_DIS_T_SEG2, &
        ELEM_2D_DIS_T_SEG2, &
        ELEM_DIS_T_POI1, ELEM_2D_DIS_T_POI1, ELEMENT_NAMES
    use model_material, only: material_field_t, material_t, material_of_cell, elastic_behaviour
    use model_cara_elem, only: cara_elem_t, CARA_NONE, REPERE_GLOBAL, ORIENT_ANGL_VRIL, &
        ORIENT_ANGL_NAUT, cara_is_diagonal, cara_is_rotational, discrete_is_unsymmetric
    use model_dof_numbering, only: dof_numbering_t, element_components, N_COMPONENTS
    use element_plate, only: plate_local_frame, plate_local_stiffness, &
        plate_section_stiffness, plate_forces_from_local, &
        rotate_to_global, plate_block_size, plate_local_blocks, plate_forces_from_blocks, &
        expand_plate_blocks, plate_section_blocks
    use model_plate_section, only: plate_section_t, plate_section, plate_section_material
    use assembly_plate_section, only: plate_cell_section
    use element_plane, only: plane_stiffness, plane_law_t
    use assembly_plane_law, only: plane_cell_law
    use element_discrete, only: dis_t_seg2_stiffness, dis_2d_t_seg2_stiffness, &
        dis_t_poi1_stiffness, dis_2d_t_poi1_stiffness, discrete_local_matrix, &
        discrete_rotate_to_global, plane_rotation, segment_rotation, segment_rotation_2d, &
        nautical_rotation
    use element_dis_choc, only: dis_choc_seg2, dis_choc_2d_seg2, dis_choc_line_seg2, &
        choc_line_t
    use element_dis_contact, only: dis_contact_seg2, dis_contact_start
    use sparse_matrix, only: sym_matrix_t, sym_pattern_from_elements, sym_zero, &
        sym_add_element, envelope_of_elements
    use renumbering, only: renumber_graph, graph_from_elements
    use huge_pages, only: advise_huge_pages
    use assembly_relations, only: elimination_t, touches_slave, element_transform, &
        reduce_element, expand_free, reduce_to_free, has_relations
    implicit none
    private

    !> Largest element vector (DKQ: 4 nodes x 6 components).
    integer(i4), parameter, public :: MAX_ELEMENT_DOFS = 24

    !> What an analysis works on (copied once from the concepts of the deck).
    type, public :: structure_t
        type(mesh_t) :: mesh
        type(model_t) :: model
        type(material_field_t) :: materials
        type(cara_elem_t) :: cara
        type(dof_numbering_t) :: dofs
        logical, allocatable :: choc(:)     !< (n_cells) a contact law (DIS_CHOC, DIS_CONTACT)
        !> (n_cells) COMPORTEMENT DIS_CONTACT on the cell (those are also choc); may be left
        !> unallocated when there is none
        logical, allocatable :: dis_contact(:)
    end type structure_t

    !> Free-equation numbering, the matrix pattern and the renumbering figures (profile and
    !> bandwidth: the envelope a skyline would store, before and after renumbering).
    type, public :: assembly_map_t
        integer(i4) :: n_free = 0
        integer(i4), allocatable :: free_eq(:)      !< (n_equations) free number, 0 = imposed
        integer(i4), allocatable :: free_to_eq(:)   !< (n_free) original equation
        logical, allocatable :: imposed(:)          !< (n_equations)
        !> the linear relations, eliminated (assembly_relations): slaves are neither free nor
        !> imposed; the matrix is T^T K T on the free equations
        type(elimination_t) :: elim
        !> (n_equations) imposed or in a relation: where REAC_NODA is f_int - f_ext
        logical, allocatable :: constrained(:)
        integer(i4), allocatable :: cells(:)        !< modelled cells with a stiffness
        !> (size(cells)) the cell has a slave equation: its matrix goes through T
        logical, allocatable :: reduced(:)
        integer(i4), allocatable :: springs(:)      !< DIS_CHOC / DIS_CONTACT cells (result order)
        integer(i4), allocatable :: spring_of(:)    !< (n_cells) index in springs, 0 = none
        character(len=:), allocatable :: renum      !< RCMK, METIS or SANS
        integer(i8) :: profile_before = 0, profile_after = 0
        integer(i4) :: bandwidth_before = 0, bandwidth_after = 0
        !> RCMK only: profile of the reverse Cuthill-McKee order when it was larger than the
        !> mesh's own order and the mesh's order was kept (0 otherwise).
        integer(i8) :: rejected_rcm_profile = 0
        type(sym_matrix_t) :: pattern               !< the matrix pattern, zero values
    end type assembly_map_t

    !> What the incremental forces K_lin du need of each linear cell (plate, plane solid),
    !> built once per analysis by the first internal_forces_incremental call that passes
    !> it: the element equations, node coordinates and the element matrix (plates: local
    !> frame and local matrix by blocks (membrane, bending, drilling: plate_local_blocks),
    !> plane solids: the 2nn x 2nn matrix). An iteration then costs one small matrix-vector
    !> product per cell instead of a rebuilt element stiffness (doc/performance.md,
    !> "SSNL130 decks"); the forces are bit for bit the same. Memory: 227 reals (1.8 kB)
    !> per DKQ cell.
    type, public :: linear_cache_t
        logical :: ready = .false.
        integer(i4), allocatable :: slot(:)         !< (size(map%cells)) cached index, 0 = none
        integer(i4), allocatable :: n(:)            !< (n_cached) element equations
        integer(i4), allocatable :: nn(:)           !< (n_cached) nodes
        logical, allocatable :: plate(:)            !< (n_cached) DKT/DKQ, else plane solid
        integer(i4), allocatable :: eqs(:, :)       !< (MAX_ELEMENT_DOFS, n_cached)
        integer(i8), allocatable :: k_ptr(:)        !< (n_cached + 1) matrix start in k
        real(dp), allocatable :: k(:)               !< the matrices, column-major
        real(dp), allocatable :: x(:, :, :)         !< (3, MAX_CELL_NODES, n_cached) nodes
        real(dp), allocatable :: rot(:, :, :)       !< (3, 3, n_cached) plate local frame
        real(dp), allocatable :: xy(:, :, :)        !< (2, 4, n_cached) plate local coords
    end type linear_cache_t

    !> State of the DIS_CONTACT springs at the start of the step (element_dis_contact), one
    !> entry per spring of map%springs (DIS_CHOC entries unused): normal force F- and
    !> normal displacement U-.
    type, public :: contact_history_t
        real(dp), allocatable :: fn0(:), un0(:)
    end type contact_history_t

    public :: structure_check, build_assembly_map, element_equations, assemble_stiffness, &
        internal_forces, internal_forces_incremental, renumbering_lines, is_dis_contact, &
        spring_block_width, gather_free, scatter_free, free_residual_max, &
        contact_history_start, contact_history_update, spring_response, spring_matrices, &
        spring_lines, linear_product, body_product, support_product, is_body_cell, &
        cell_response, discrete_matrix, build_linear_cache

contains

    !> Checks that every modelled cell has what its element needs: ELAS (plates, plane
    !> solids; plates also ELAS_FO, ELAS_COQUE, laminates; plane solids ELAS_ORTH), COQUE (plates), DISCRET (springs), DIS_CONTACT (DIS_CHOC and DIS_CONTACT
    !> springs; SEG2 only).
    !>  st : out, STATUS_MODEL_ERROR naming the cell (and its group when given), or
    !>       STATUS_NOT_IMPLEMENTED for a contact law on a POI1 or with COULOMB
    subroutine structure_check(s, st, group_of)
        type(structure_t), intent(in) :: s
        type(status_t), intent(out) :: st
        character(len=*), intent(in), optional :: group_of
        integer(i4) :: c, kind, m
        character(len=:), allocatable :: what, law
        type(string_t), allocatable :: laws(:)     ! each material's elastic law, once
        if (allocated(s%materials%materials)) then
            allocate (laws(size(s%materials%materials)))
        else
            allocate (laws(0))                     ! no material: m is 0 for every cell
        end if
        do c = 1, s%mesh%n_cells
            kind = s%model%element(c)
            if (kind == ELEM_NONE .or. is_load_edge(kind)) cycle
            m = material_of_cell(s%materials, c)
            what = ''
            if (is_plate(kind) .or. is_plane_solid(kind)) then
                ! (each test in its own branch: Fortran's .and. does not short-circuit, and
                ! the behaviour's name costs a search through the material's behaviours)
                if (m == 0) then
                    what = 'no material (AFFE_MATERIAU)'
                else if (s%materials%materials(m)%has_elas) then
                    what = ''
                else if (is_plate(kind) .and. &
                         plate_section_material(s%materials%materials(m))) then
                    what = ''                  ! ELAS_COQUE, laminates (model_plate_section)
                else
                    law = material_law(m)
                    if (is_plane_solid(kind) .and. law == 'ELAS_ORTH') then
                        what = ''              ! orthotropic plane law (assembly_plane_law)
                    else if (is_plane_solid(kind) .and. law == 'ELAS_FO') then
                        what = ''              ! ELAS_FO's E, NU (assembly_plane_law)
                    else
                        what = 'no ELAS in its material'
                        if (is_plate(kind) .and. law == 'ELAS_ORTH') then
                            call set_error(st, STATUS_MODEL_ERROR, cell_label(s%mesh, c, &
                                group_of) // ' (' // trim(ELEMENT_NAMES(kind)) // '): its ' // &
                                'material gives ELAS_ORTH to a DKT plate: Code_Aster ' // &
                                'refuses it (ELEMENTS_91); give the layers through ' // &
                                'DEFI_COMPOSITE')
                            return
                        end if
                        if (len(law) > 0) then
                            call set_error(st, STATUS_NOT_IMPLEMENTED, cell_label(s%mesh, &
                                c, group_of) // ' (' // trim(ELEMENT_NAMES(kind)) // '): ' // &
                                'its material gives ' // law // ', which parasol''s ' // &
                                'element does not build yet (it takes ELAS: E, NU)')
                            return
                        end if
                    end if
                end if
                if (is_plate(kind) .and. .not. s%cara%has_coque(c)) &
                    what = 'no COQUE thickness (AFFE_CARA_ELEM)'
            else if (is_discrete(kind)) then
                if (s%cara%discrete_cara(c) == CARA_NONE) &
                    what = 'no DISCRET stiffness (AFFE_CARA_ELEM DISCRET or RIGI_PARASOL)'
                if (s%choc(c) .and. len(what) == 0) then
                    law = trim(merge('DIS_CONTACT', 'DIS_CHOC   ', is_dis_contact(s, c)))
                    if (m == 0) then
                        what = law // ' but no material (AFFE_MATERIAU with DIS_CONTACT)'
                    else if (.not. s%materials%materials(m)%has_dis_contact) then
                        what = law // ' but no DIS_CONTACT in its material'
                    else if (is_discrete_rotational(kind)) then
                        call set_error(st, STATUS_NOT_IMPLEMENTED, law // ' on ' // &
                            cell_label(s%mesh, c, group_of) // ' (' // &
                            trim(ELEMENT_NAMES(kind)) // ') is not built; use DIS_T or ' // &
                            '2D_DIS_T springs')
                        return
                    else if (s%mesh%cell_type(c) == CELL_POI1) then
                        call set_error(st, STATUS_NOT_IMPLEMENTED, law // ' on ' // &
                            cell_label(s%mesh, c, group_of) // ' (POI1) is not built; ' // &
                            'use SEG2 springs')
                        return
                    else if (s%materials%materials(m)%dis_contact%coulomb > 0.0_dp) then
                        call set_error(st, STATUS_NOT_IMPLEMENTED, 'DIS_CONTACT COULOMB ' // &
                            '(friction) on ' // cell_label(s%mesh, c, group_of) // &
                            ' is not built; use COULOMB = 0')
                        return
                    end if
                end if
            end if
            if (len(what) > 0) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(s%mesh, c, group_of) // &
                    ' (' // trim(ELEMENT_NAMES(kind)) // ') has ' // what)
                return
            end if
        end do
    contains
        ! elastic_behaviour of material m, looked up once per material
        function material_law(m) result(name)
            integer(i4), intent(in) :: m
            character(len=:), allocatable :: name
            if (.not. allocated(laws(m)%s)) laws(m)%s = &
                elastic_behaviour(s%materials%materials(m))
            name = laws(m)%s
        end function material_law
    end subroutine structure_check

    !> Original equations of a cell, node by node, its element's components in order.
    !>  n : out, number of equations (size of the element vectors)
    subroutine element_equations(s, c, eqs, n)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        integer(i4), intent(out) :: eqs(MAX_ELEMENT_DOFS), n
        logical :: mask(N_COMPONENTS)
        integer(i4) :: p, comp
        mask = element_components(s%model%element(c))
        n = 0
        eqs = 0
        do p = s%mesh%cell_ptr(c), s%mesh%cell_ptr(c + 1) - 1
            do comp = 1, N_COMPONENTS
                if (.not. mask(comp)) cycle
                n = n + 1
                eqs(n) = s%dofs%equation(comp, s%mesh%cell_nodes(p))
            end do
        end do
    end subroutine element_equations

    !> Numbers the free equations (nodes renumbered by `renum`, then their components
    !> neither imposed nor slaves of a relation, in order) and builds the matrix pattern;
    !> records the envelope (profile, bandwidth) before (original node order) and after
    !> renumbering.
    !>  imposed : in, (n_equations) .true. for the equations of DDL_IMPO
    !>  renum   : in, 'RCMK' (default of Code_Aster LDLT), 'METIS' or 'SANS' (back-ends with
    !>            an ordering of their own get 'SANS')
    !>  st      : out, unknown method, or a renumbering/pattern failure
    !>  elim    : inout, optional, the eliminated relations (moved into the map)
    !>  rigid   : in, optional, (n_cells) cells inside a rigid body (LIAISON_SOLIDE): they
    !>            store no energy under its relations and are left out
    subroutine build_assembly_map(s, imposed, renum, map, st, elim, rigid)
        type(structure_t), intent(in) :: s
        logical, intent(in) :: imposed(:)
        character(len=*), intent(in) :: renum
        type(assembly_map_t), intent(out) :: map
        type(status_t), intent(out) :: st
        type(elimination_t), intent(inout), optional :: elim
        logical, intent(in), optional :: rigid(:)
        integer(i4), allocatable :: identity(:), new_to_old(:), old_to_new(:), xadj(:), adjncy(:)
        integer(i4), allocatable :: ptr(:), eqs_all(:)
        integer(i4) :: c, n_cells, k, n, eqs(MAX_ELEMENT_DOFS)
        logical, allocatable :: eliminated(:)
        if (present(elim)) then
            call move_elimination(elim, map%elim)
        else
            allocate (map%elim%slave_of(s%dofs%n_equations), source=0_i4)
            allocate (map%elim%in_relation(s%dofs%n_equations), source=.false.)
        end if
        map%constrained = imposed .or. map%elim%in_relation
        eliminated = imposed .or. map%elim%slave_of > 0
        map%imposed = imposed
        map%renum = renum
        n_cells = 0
        allocate (map%cells(s%mesh%n_cells), map%springs(s%mesh%n_cells))
        k = 0
        do c = 1, s%mesh%n_cells
            if (s%model%element(c) == ELEM_NONE .or. is_load_edge(s%model%element(c))) cycle
            if (present(rigid)) then
                if (rigid(c)) cycle
            end if
            n_cells = n_cells + 1
            map%cells(n_cells) = c
            if (s%choc(c) .and. is_discrete(s%model%element(c))) then
                k = k + 1
                map%springs(k) = c
            end if
        end do
        map%cells = map%cells(1:n_cells)
        map%springs = map%springs(1:k)
        allocate (map%spring_of(s%mesh%n_cells), source=0_i4)
        do k = 1, size(map%springs)
            map%spring_of(map%springs(k)) = k
        end do
        allocate (map%reduced(n_cells))
        do k = 1, n_cells
            call element_equations(s, map%cells(k), eqs, n)
            map%reduced(k) = touches_slave(map%elim, eqs(1:n))
        end do
        call node_graph(s, map%cells, map%elim, xadj, adjncy, st)
        if (st%failed()) return
        call renumber_graph(renum, s%mesh%n_nodes, xadj, adjncy, new_to_old, old_to_new, st)
        if (st%failed()) return
        identity = [(k, k = 1, s%mesh%n_nodes)]
        call number_free(s, eliminated, identity, map)
        call element_free_equations(s, map, ptr, eqs_all)
        call envelope_of_elements(map%n_free, ptr, eqs_all, map%profile_before, &
            map%bandwidth_before)
        if (renum == 'SANS') then
            ! the mesh order itself (and the order of the back-ends that order themselves):
            ! the numbering above is the final one
            map%profile_after = map%profile_before
            map%bandwidth_after = map%bandwidth_before
        else
            call number_free(s, eliminated, new_to_old, map)
            call element_free_equations(s, map, ptr, eqs_all)
            call envelope_of_elements(map%n_free, ptr, eqs_all, map%profile_after, &
                map%bandwidth_after)
        end if
        ! Cuthill-McKee from a corner of a structured plate grows diagonal fronts: on the
        ! SSNL130 plates and square plates its profile is 5-25 % larger than the mesh's own
        ! row-by-row order. The skyline cost follows the profile, so RCMK never makes it
        ! worse: the mesh's order is kept when it is smaller, and the .mess says so.
        if (renum == 'RCMK' .and. map%profile_after > map%profile_before) then
            map%rejected_rcm_profile = map%profile_after
            call number_free(s, eliminated, identity, map)
            call element_free_equations(s, map, ptr, eqs_all)
            map%profile_after = map%profile_before
            map%bandwidth_after = map%bandwidth_before
        end if
        call sym_pattern_from_elements(map%pattern, map%n_free, ptr, eqs_all, st)
    end subroutine build_assembly_map

    !> Node graph of the cells with a stiffness, and of the relations (the nodes of each
    !> relation linked as a cell's are: eliminating a slave couples its masters with its
    !> neighbours, and the orderings should see it).
    subroutine node_graph(s, cells, elim, xadj, adjncy, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: cells(:)
        type(elimination_t), intent(in) :: elim
        integer(i4), allocatable, intent(out) :: xadj(:), adjncy(:)
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: ptr(:), nodes(:)
        integer(i4) :: k, c, n, n_rows, r, m
        n_rows = 0
        if (allocated(elim%rows%ptr)) n_rows = elim%rows%n
        allocate (ptr(size(cells) + n_rows + 1))
        ptr(1) = 1
        do k = 1, size(cells)
            c = cells(k)
            ptr(k + 1) = ptr(k) + s%mesh%cell_ptr(c + 1) - s%mesh%cell_ptr(c)
        end do
        m = size(cells, kind=i4)
        do r = 1, n_rows
            ptr(m + r + 1) = ptr(m + r) + elim%rows%ptr(r + 1) - elim%rows%ptr(r)
        end do
        allocate (nodes(ptr(size(ptr)) - 1))
        do k = 1, size(cells)
            c = cells(k)
            n = s%mesh%cell_ptr(c + 1) - s%mesh%cell_ptr(c)
            nodes(ptr(k):ptr(k + 1) - 1) = s%mesh%cell_nodes(s%mesh%cell_ptr(c): &
                s%mesh%cell_ptr(c + 1) - 1)
        end do
        do r = 1, n_rows
            nodes(ptr(m + r):ptr(m + r + 1) - 1) = s%dofs%equation_node(elim%rows%eq( &
                elim%rows%ptr(r):elim%rows%ptr(r + 1) - 1))
        end do
        call graph_from_elements(s%mesh%n_nodes, ptr, nodes, xadj, adjncy, st)
    end subroutine node_graph

    !> Free equation numbers in the node order `order` (new_to_old).
    !>  imposed : in, (n_equations) the equations that are not free (imposed, slaves)
    subroutine number_free(s, imposed, order, map)
        type(structure_t), intent(in) :: s
        logical, intent(in) :: imposed(:)
        integer(i4), intent(in) :: order(:)
        type(assembly_map_t), intent(inout) :: map
        integer(i4) :: k, comp, eq
        if (allocated(map%free_eq)) deallocate (map%free_eq)
        allocate (map%free_eq(s%dofs%n_equations), source=0_i4)
        map%n_free = 0
        do k = 1, size(order)
            do comp = 1, N_COMPONENTS
                eq = s%dofs%equation(comp, order(k))
                if (eq <= 0) cycle
                if (imposed(eq)) cycle
                map%n_free = map%n_free + 1
                map%free_eq(eq) = map%n_free
            end do
        end do
        if (allocated(map%free_to_eq)) deallocate (map%free_to_eq)
        allocate (map%free_to_eq(map%n_free))
        do eq = 1, s%dofs%n_equations
            if (map%free_eq(eq) > 0) map%free_to_eq(map%free_eq(eq)) = eq
        end do
    end subroutine number_free

    !> Free equations of every cell with a stiffness, in CSR form (ptr, eqs; 0 = imposed);
    !> a cell with slave equations gets the free equations its slaves depend on.
    subroutine element_free_equations(s, map, ptr, eqs_all)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), allocatable, intent(out) :: ptr(:), eqs_all(:)
        integer(i4) :: k, n, m, eqs(MAX_ELEMENT_DOFS)
        integer(i4), allocatable :: red(:), grown(:)
        real(dp), allocatable :: te(:, :)
        allocate (ptr(size(map%cells) + 1), eqs_all(MAX_ELEMENT_DOFS * size(map%cells)))
        ptr(1) = 1
        do k = 1, size(map%cells)
            call element_equations(s, map%cells(k), eqs, n)
            if (map%reduced(k)) then
                call element_transform(map%elim, map%free_eq, eqs(1:n), red, te, m)
                if (ptr(k) + m - 1 > size(eqs_all)) then
                    allocate (grown(2 * (ptr(k) + m)))
                    grown(1:ptr(k) - 1) = eqs_all(1:ptr(k) - 1)
                    call move_alloc(grown, eqs_all)
                end if
                eqs_all(ptr(k):ptr(k) + m - 1) = red
                ptr(k + 1) = ptr(k) + m
                cycle
            end if
            if (ptr(k) + n - 1 > size(eqs_all)) then
                allocate (grown(2 * (ptr(k) + n)))
                grown(1:ptr(k) - 1) = eqs_all(1:ptr(k) - 1)
                call move_alloc(grown, eqs_all)
            end if
            eqs_all(ptr(k):ptr(k) + n - 1) = free_of(map, eqs(1:n))
            ptr(k + 1) = ptr(k) + n
        end do
        eqs_all = eqs_all(1:ptr(size(ptr)) - 1)
    end subroutine element_free_equations

    !> Free numbers of original equations (0 for imposed or absent ones).
    pure function free_of(map, eqs) result(free)
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: eqs(:)
        integer(i4) :: free(size(eqs)), k
        do k = 1, size(eqs)
            free(k) = 0
            if (eqs(k) > 0) free(k) = map%free_eq(eqs(k))
        end do
    end function free_of

    !> .mess lines on the renumbering: method, equations, profile and bandwidth before/after.
    function renumbering_lines(map) result(lines)
        type(assembly_map_t), intent(in) :: map
        character(len=100) :: lines(2)
        lines(1) = 'RENUM ' // map%renum // ': ' // to_text(map%n_free) // &
            ' free equations'
        lines(2) = 'profile ' // to_text(map%profile_before) // ' -> ' // &
            to_text(map%profile_after) // ' terms, bandwidth ' // &
            to_text(map%bandwidth_before) // ' -> ' // to_text(map%bandwidth_after)
        if (map%rejected_rcm_profile > 0) lines(2) = trim(lines(2)) // &
            ' (mesh order kept: RCM gave ' // to_text(map%rejected_rcm_profile) // ')'
    end function renumbering_lines

    !> Element matrix and internal forces of one cell at element displacements ue.
    !>  elastic : in, DIS_CHOC / DIS_CONTACT springs give their elastic (closed) matrix
    !>  closed  : out, contact status (.true. for other elements); fn : out, normal force
    !>  history : in, optional, DIS_CONTACT state at the start of the step (absent: the
    !>            state before the first step)
    subroutine cell_response(s, c, ue, n, elastic, want_matrix, ke, fe, closed, fn, st, &
                             map, history)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, n
        real(dp), intent(in) :: ue(n)
        logical, intent(in) :: elastic, want_matrix
        real(dp), intent(out) :: ke(n, n), fe(n), fn
        logical, intent(out) :: closed
        type(status_t), intent(out) :: st
        type(assembly_map_t), intent(in), optional :: map
        type(contact_history_t), intent(in), optional :: history
        integer(i4) :: kind, m, nn, p0
        real(dp) :: x(3, MAX_CELL_NODES), x2(2, MAX_CELL_NODES), ud(MAX_ELEMENT_DOFS)
        type(plane_law_t) :: law
        real(dp) :: rot(3, 3), xy(2, 4), k18(18, 18), k24(24, 24)
        kind = s%model%element(c)
        p0 = s%mesh%cell_ptr(c)
        nn = s%mesh%cell_ptr(c + 1) - p0
        x(:, 1:nn) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
        m = material_of_cell(s%materials, c)
        closed = .true.
        fn = 0.0_dp
        ke = 0.0_dp
        fe = 0.0_dp
        if (is_plate(kind) .and. nn == 3) then
            call plate_cell_local(s, c, x(:, 1:nn), nn, rot, xy, k18, st)
            if (st%ok() .and. want_matrix) then
                call rotate_to_global(rot, 6_i4, k18, ke)
            else if (st%ok()) then
                call plate_forces_from_local(rot, xy(:, 1:nn), nn, k18, &
                    plate_deformation(x(:, 1:nn), nn, ue), fe)
            end if
        else if (is_plate(kind)) then
            call plate_cell_local(s, c, x(:, 1:nn), nn, rot, xy, k24, st)
            if (st%ok() .and. want_matrix) then
                call rotate_to_global(rot, 8_i4, k24, ke)
            else if (st%ok()) then
                call plate_forces_from_local(rot, xy(:, 1:nn), nn, k24, &
                    plate_deformation(x(:, 1:nn), nn, ue), fe)
            end if
        else if (is_plane_solid(kind)) then
            x2(:, 1:nn) = x(1:2, 1:nn)
            call plane_cell_law(s%mesh, s%model, s%materials, s%cara, c, law, st)
            if (st%ok()) call plane_stiffness(s%mesh%cell_type(c), x2(:, 1:nn), law%d3, ke, st)
            if (.not. want_matrix .and. st%ok()) then
                ! the deformation in a variable of its own: matmul of a function result,
                ! inlined by the front end, read an uninitialised temporary (valgrind)
                call remove_plane_rigid_motion(x2(:, 1:nn), nn, ue, ud(1:n))
                fe = matmul(ke, ud(1:n))
            end if
        else if (is_dis_contact(s, c)) then
            call dis_contact_response(s, c, x, ue, n, elastic, ke, fe, closed, fn, st, map, &
                history)
        else
            call discrete_response(s, c, x, ue, n, elastic, ke, fe, closed, fn, st)
            ! SYME='NON': the matrices hold the symmetric part; the analysis corrects for
            ! the skew part (assembly_unsymmetric); the forces above used K whole
            if (want_matrix .and. discrete_is_unsymmetric(s%cara, c)) &
                ke = 0.5_dp * (ke + transpose(ke))
        end if
        if (st%failed()) call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // &
            st%message)
    end subroutine cell_response

    !> The local frame and local stiffness of plate cell c (element_plate) from its section
    !> (assembly_plate_section): isotropic and centred sections through plate_local_stiffness
    !> (E, NU, EPAIS), the others (ELAS_COQUE, laminates, EXCENTREMENT) through
    !> plate_section_stiffness.
    subroutine plate_cell_local(s, c, x, nn, rot, xy, kl, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, nn
        real(dp), intent(in) :: x(3, nn)
        real(dp), intent(out) :: rot(3, 3), xy(2, 4), kl(6 * nn, 6 * nn)
        type(status_t), intent(out) :: st
        type(plate_section_t) :: sec
        kl = 0.0_dp
        xy = 0.0_dp
        if (nn /= 3 .and. nn /= 4) then
            call set_error(st, STATUS_MODEL_ERROR, 'DKT plates need TRIA3 or QUAD4 cells')
            return
        end if
        call plate_local_frame(x, nn, rot, xy(:, 1:nn), st)
        if (st%ok()) call plate_cell_section(s%mesh, s%materials, s%cara, c, rot, sec, st)
        if (st%failed()) return
        if (sec%isotropic .and. .not. sec%coupled) then
            call plate_local_stiffness(xy(:, 1:nn), nn, sec%young, sec%nu, sec%thickness, &
                s%cara%coef_rigi_drz(c), kl, st)
        else
            call plate_section_stiffness(xy(:, 1:nn), nn, sec%dm, sec%dmf, sec%df, &
                s%cara%coef_rigi_drz(c), kl, st)
        end if
    end subroutine plate_cell_local

    ! True when the section of plate cell c couples membrane and bending (its blocks then
    ! hold the coupling block; a section that cannot be built says no: the matrix reports).
    logical function plate_cell_coupled(s, c)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        type(plate_section_t) :: sec
        type(status_t) :: st
        integer(i4) :: m
        plate_cell_coupled = .false.
        m = material_of_cell(s%materials, c)
        if (m == 0) return
        call plate_section(s%materials%materials(m), s%cara, c, sec, st)
        plate_cell_coupled = st%ok() .and. sec%coupled
    end function plate_cell_coupled

    !> True when cell c follows COMPORTEMENT RELATION = 'DIS_CONTACT'.
    pure logical function is_dis_contact(s, c)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        is_dis_contact = .false.
        if (allocated(s%dis_contact)) is_dis_contact = s%dis_contact(c)
    end function is_dis_contact

    !> The discrete's own stiffness matrix (DISCRET / RIGI_PARASOL values, orientation:
    !> ORIENTATION's angles are degrees, as Code_Aster's). Diagonal translational ones
    !> (K_T_D_*) through the DIS_T kernels; the others (DIS_TR, full matrices) through
    !> discrete_local_matrix / discrete_rotate_to_global (element_discrete).
    subroutine discrete_matrix(s, c, x, n, ke, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, n
        real(dp), intent(in) :: x(:, :)
        real(dp), intent(out) :: ke(n, n)
        type(status_t), intent(out) :: st
        real(dp), parameter :: DEGREE = acos(-1.0_dp) / 180.0_dp
        integer(i4) :: kind, code
        real(dp) :: kv(6), angles(3), k6(6, 6), k4(4, 4), c3(3, 2), c2(2, 2)
        logical :: global
        kind = s%model%element(c)
        code = s%cara%discrete_cara(c)
        c3 = x(1:3, 1:2)
        c2 = x(1:2, 1:2)
        kv = s%cara%discrete_values(:, c)
        global = s%cara%discrete_repere(c) == REPERE_GLOBAL
        angles = 0.0_dp
        if (s%cara%orientation(c) == ORIENT_ANGL_VRIL) angles(3) = &
            s%cara%orientation_values(1, c) * DEGREE
        if (s%cara%orientation(c) == ORIENT_ANGL_NAUT) angles = &
            s%cara%orientation_values(:, c) * DEGREE
        ke = 0.0_dp
        ! a 2D discrete turned by ANGL_NAUT with BETA or GAMMA: the general path (the XY
        ! block of the 3D rotation, as Code_Aster turns it; zzzz274b)
        if (.not. (cara_is_diagonal(code) .and. .not. cara_is_rotational(code)) .or. &
            (kind == ELEM_2D_DIS_T_POI1 .and. any(abs(angles(2:3)) > 0.0_dp))) then
            call general_discrete_matrix(s, c, x, n, kv, global, angles, ke, st)
            return
        end if
        select case (kind)
        case (ELEM_DIS_T_SEG2)
            call dis_t_seg2_stiffness(c3, kv(1:3), global, angles(3), k6, st)
            ke = k6
        case (ELEM_2D_DIS_T_SEG2)
            call dis_2d_t_seg2_stiffness(c2, kv(1:2), global, k4, st)
            ke = k4
        case (ELEM_DIS_T_POI1)
            call dis_t_poi1_stiffness(kv(1:3), global, angles, ke)
        case (ELEM_2D_DIS_T_POI1)
            call dis_2d_t_poi1_stiffness(kv(1:2), global, angles(1), ke)
        end select
    end subroutine discrete_matrix

    ! A DIS_TR / 2D_DIS_TR discrete, or a full matrix (K_T_N, K_T_L, K_TR_N, K_TR_L): the
    ! matrix in the discrete's frame, turned to the global one unless REPERE='GLOBAL'. The
    ! frame: a SEG2's (local x along it, ANGL_VRIL), a POI1's ORIENTATION (2D: its first
    ! angle about Z).
    subroutine general_discrete_matrix(s, c, x, n, kv, global, angles, ke, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, n
        real(dp), intent(in) :: x(:, :), kv(6), angles(3)
        logical, intent(in) :: global
        real(dp), intent(out) :: ke(n, n)
        type(status_t), intent(out) :: st
        integer(i4) :: kind, n_nodes, node_dofs, id
        real(dp) :: kl(n, n), r(3, 3), r2(2, 2)
        logical :: two_d
        kind = s%model%element(c)
        two_d = is_discrete_2d(kind)
        n_nodes = merge(1_i4, 2_i4, s%mesh%cell_type(c) == CELL_POI1)
        node_dofs = n / n_nodes
        id = s%cara%discrete_matrix(c)
        if (id > 0) then
            kl = s%cara%matrices(id)%k
        else
            call discrete_local_matrix(kv(1:node_dofs), n_nodes, kl)
        end if
        if (global) then
            ke = kl
            return
        end if
        if (n_nodes == 2 .and. two_d) then
            call segment_rotation_2d(x(1:2, 1), x(1:2, 2), r2, st)
            r = 0.0_dp
            r(1:2, 1:2) = r2
            r(3, 3) = 1.0_dp
        else if (n_nodes == 2) then
            call segment_rotation(x(1:3, 1), x(1:3, 2), angles(3), r, st)
        else if (two_d .and. any(abs(angles(2:3)) > 0.0_dp)) then
            ! ANGL_NAUT with BETA or GAMMA on a 2D discrete: Code_Aster turns its matrix
            ! by the 3D rotation and keeps the XY block (zzzz274b: the GLOBAL matrix it
            ! gives equals the LOCAL one turned so)
            call nautical_rotation(angles, r)
        else if (two_d) then
            r = plane_rotation(angles(1))
        else
            call nautical_rotation(angles, r)
        end if
        if (st%failed()) return
        call discrete_rotate_to_global(kl, n_nodes, node_dofs, two_d, r, ke)
    end subroutine general_discrete_matrix

    !> DIS_CONTACT on a SEG2 (element_dis_contact), from the spring's state at the start of
    !> the step (history) or, without one, the state before the first step.
    subroutine dis_contact_response(s, c, x, ue, n, elastic, ke, fe, closed, fn, st, map, &
                                    history)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, n
        real(dp), intent(in) :: x(:, :), ue(n)
        logical, intent(in) :: elastic
        real(dp), intent(out) :: ke(n, n), fe(n), fn
        logical, intent(out) :: closed
        type(status_t), intent(out) :: st
        type(assembly_map_t), intent(in), optional :: map
        type(contact_history_t), intent(in), optional :: history
        integer(i4) :: m, d, k
        real(dp) :: fn0, un0, un
        real(dp), allocatable :: kd(:, :), kblock(:, :), xd(:, :)
        closed = .false.
        fn = 0.0_dp
        fe = 0.0_dp
        allocate (kd(n, n))
        call discrete_matrix(s, c, x, n, kd, st)
        if (st%failed()) return
        d = n / 2
        kblock = kd(1:d, 1:d)       ! contiguous copies for the law (no array temporaries)
        xd = x(1:d, 1:2)
        m = material_of_cell(s%materials, c)
        associate (dc => s%materials%materials(m)%dis_contact)
            k = 0
            if (present(history) .and. present(map)) k = map%spring_of(c)
            if (k > 0) then
                fn0 = history%fn0(k)
                un0 = history%un0(k)
            else if (dc%has_rigi_nor) then
                call dis_contact_start(d, xd, kblock, dc%dist_1, dc%dist_2, fn0, un0, st, &
                    dc%rigi_nor)
            else
                call dis_contact_start(d, xd, kblock, dc%dist_1, dc%dist_2, fn0, un0, st)
            end if
            if (st%failed()) return
            if (dc%has_rigi_nor) then
                call dis_contact_seg2(d, xd, ue, kblock, dc%dist_1, dc%dist_2, fn0, un0, &
                    elastic, closed, fn, un, fe, ke, st, dc%rigi_nor)
            else
                call dis_contact_seg2(d, xd, ue, kblock, dc%dist_1, dc%dist_2, fn0, un0, &
                    elastic, closed, fn, un, fe, ke, st)
            end if
            if (elastic .and. st%ok()) ke = kd
        end associate
    end subroutine dis_contact_response

    !> The DIS_CONTACT springs' state before the first step (dis_contact_start).
    !>  history : out, sized to map%springs (DIS_CHOC entries 0)
    !>  st      : out, a zero-length spring, naming the cell
    subroutine contact_history_start(s, map, history, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(contact_history_t), intent(out) :: history
        type(status_t), intent(out) :: st
        integer(i4) :: k, c, n, d, m, p0
        real(dp) :: x(3, 4)
        real(dp), allocatable :: kd(:, :), kblock(:, :), xd(:, :)
        allocate (history%fn0(size(map%springs)), history%un0(size(map%springs)), &
            source=0.0_dp)
        do k = 1, size(map%springs)
            c = map%springs(k)
            if (.not. is_dis_contact(s, c)) cycle
            p0 = s%mesh%cell_ptr(c)
            x = 0.0_dp
            x(:, 1:2) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + 1))
            n = merge(4_i4, 6_i4, is_discrete_2d(s%model%element(c)))
            d = n / 2
            if (allocated(kd)) deallocate (kd)
            allocate (kd(n, n))
            call discrete_matrix(s, c, x, n, kd, st)
            kblock = kd(1:d, 1:d)
            xd = x(1:d, 1:2)
            m = material_of_cell(s%materials, c)
            associate (dc => s%materials%materials(m)%dis_contact)
                if (st%ok() .and. dc%has_rigi_nor) then
                    call dis_contact_start(d, xd, kblock, dc%dist_1, dc%dist_2, &
                        history%fn0(k), history%un0(k), st, dc%rigi_nor)
                else if (st%ok()) then
                    call dis_contact_start(d, xd, kblock, dc%dist_1, dc%dist_2, &
                        history%fn0(k), history%un0(k), st)
                end if
            end associate
            if (st%failed()) then
                call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // st%message)
                return
            end if
        end do
    end subroutine contact_history_start

    !> At the end of a converged step: F- = the springs' normal forces fn, U- = their normal
    !> displacement (u2 - u1) . e at u.
    subroutine contact_history_update(s, map, u, fn, history)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:), fn(:)
        type(contact_history_t), intent(inout) :: history
        integer(i4) :: k, c, n, d, p0, eqs(MAX_ELEMENT_DOFS)
        real(dp) :: e(3), ue(MAX_ELEMENT_DOFS)
        do k = 1, size(map%springs)
            c = map%springs(k)
            if (.not. is_dis_contact(s, c)) cycle
            call element_equations(s, c, eqs, n)
            call gather_into(u, eqs, n, ue)
            d = n / 2
            p0 = s%mesh%cell_ptr(c)
            e(1:d) = s%mesh%coords(1:d, s%mesh%cell_nodes(p0 + 1)) - &
                s%mesh%coords(1:d, s%mesh%cell_nodes(p0))
            e(1:d) = e(1:d) / norm2(e(1:d))
            history%fn0(k) = fn(k)
            history%un0(k) = dot_product(ue(d + 1:2 * d) - ue(1:d), e(1:d))
        end do
    end subroutine contact_history_update

    !> Springs: linear DIS_T / 2D_DIS_T, or DIS_CHOC on SEG2.
    subroutine discrete_response(s, c, x, ue, n, elastic, ke, fe, closed, fn, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, n
        real(dp), intent(in) :: x(:, :), ue(n)
        logical, intent(in) :: elastic
        real(dp), intent(out) :: ke(n, n), fe(n), fn
        logical, intent(out) :: closed
        type(status_t), intent(out) :: st
        integer(i4) :: kind, m
        real(dp) :: gap, k3(3, 3), k2(2, 2), c3(3, 2), c2(2, 2)
        kind = s%model%element(c)
        c3 = x(:, 1:2)
        c2 = x(1:2, 1:2)
        closed = .true.
        fn = 0.0_dp
        call discrete_matrix(s, c, x, n, ke, st)
        if (st%failed()) return
        if (.not. s%choc(c)) then
            fe = matmul(ke, ue)
            return
        end if
        m = material_of_cell(s%materials, c)
        associate (dc => s%materials%materials(m)%dis_contact)
            if (kind == ELEM_DIS_T_SEG2) then
                k3 = ke(1:3, 1:3)
                if (dc%has_rigi_nor) then
                    call dis_choc_seg2(c3, ue, k3, dc%dist_1, dc%dist_2, &
                        elastic, closed, gap, fn, fe, ke, st, dc%rigi_nor, dc%rigi_tan)
                else
                    call dis_choc_seg2(c3, ue, k3, dc%dist_1, dc%dist_2, &
                        elastic, closed, gap, fn, fe, ke, st, rigi_tan=dc%rigi_tan)
                end if
            else
                k2 = ke(1:2, 1:2)
                if (dc%has_rigi_nor) then
                    call dis_choc_2d_seg2(c2, ue, k2, dc%dist_1, &
                        dc%dist_2, elastic, closed, gap, fn, fe, ke, st, dc%rigi_nor, &
                        dc%rigi_tan)
                else
                    call dis_choc_2d_seg2(c2, ue, k2, dc%dist_1, &
                        dc%dist_2, elastic, closed, gap, fn, fe, ke, st, rigi_tan=dc%rigi_tan)
                end if
            end if
        end associate
    end subroutine discrete_response

    !> Plane displacements minus their rigid motion (mean translation and the rotation
    !> about Z fitted about the centroid of the nodes). K times a rigid motion is zero, so
    !> f_int is unchanged, but the round-off of K u no longer scales with the (large) rigid
    !> part: in SSNL130 the slab is ~1e8 times stiffer than the springs and moves ~3.5e-3
    !> rigidly.
    !>  x : in, x(2, nn) node coordinates; ue : in, ue(2 nn); ud : out, ud(2 nn)
    pure subroutine remove_plane_rigid_motion(x, nn, ue, ud)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: x(2, nn), ue(2 * nn)
        real(dp), intent(out) :: ud(2 * nn)
        real(dp) :: xc(2), uc(2), d(2), num, den, omega
        integer(i4) :: i
        xc = sum(x, dim=2) / real(nn, dp)
        uc = [sum(ue(1:2 * nn - 1:2)), sum(ue(2:2 * nn:2))] / real(nn, dp)
        num = 0.0_dp
        den = 0.0_dp
        do i = 1, nn
            d = x(:, i) - xc
            num = num + d(1) * (ue(2 * i) - uc(2)) - d(2) * (ue(2 * i - 1) - uc(1))
            den = den + d(1)**2 + d(2)**2
        end do
        omega = 0.0_dp
        if (den > 0.0_dp) omega = num / den
        do i = 1, nn
            d = x(:, i) - xc
            ud(2 * i - 1) = ue(2 * i - 1) - uc(1) + omega * d(2)
            ud(2 * i) = ue(2 * i) - uc(2) - omega * d(1)
        end do
    end subroutine remove_plane_rigid_motion

    !> Plate (DX..DRZ per node) displacements minus a rigid motion: the mean translation
    !> and the mean rotation about the in-plane axes (u = t + w x P(x - xc), P the
    !> projection on the cell's mean plane, theta = w,
    !> w normal to the plate). That motion has zero energy in DKT/DKQ (a rotation about the
    !> normal would load the fictitious DRZ stiffness, so it is left in); removing it keeps
    !> the round-off of K u proportional to the deformation (see remove_plane_rigid_motion).
    pure function plate_deformation(x, nn, ue) result(ud)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: x(3, nn), ue(6 * nn)
        real(dp) :: ud(6 * nn)
        call remove_plate_rigid_motion(x, nn, ue, ud)
    end function plate_deformation

    !> plate_deformation as a subroutine (the caller's array, no function-result temporary).
    pure subroutine remove_plate_rigid_motion(x, nn, ue, ud)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: x(3, nn), ue(6 * nn)
        real(dp), intent(out) :: ud(6 * nn)
        real(dp) :: xc(3), t(3), w(3), n(3), d(3)
        integer(i4) :: i
        if (nn == 4) then
            n = cross(x(:, 3) - x(:, 1), x(:, 4) - x(:, 2))
        else
            n = cross(x(:, 2) - x(:, 1), x(:, 3) - x(:, 1))
        end if
        ud = ue
        if (.not. norm2(n) > 0.0_dp) return
        n = n / norm2(n)
        xc = sum(x, dim=2) / real(nn, dp)
        t = 0.0_dp
        w = 0.0_dp
        do i = 1, nn
            t = t + ue(6 * i - 5:6 * i - 3)
            w = w + ue(6 * i - 2:6 * i)
        end do
        t = t / real(nn, dp)
        w = w / real(nn, dp)
        w = w - dot_product(w, n) * n
        do i = 1, nn
            ! the arm in the cell's mean plane (plate_local_frame's normal): the element is
            ! built on the nodes projected there, so only that motion has zero energy; a
            ! warped cell's out-of-plane offsets would otherwise turn the rotation into a
            ! membrane stretch K does not see as rigid (internal forces != K u)
            d = x(:, i) - xc
            d = d - dot_product(d, n) * n
            ud(6 * i - 5:6 * i - 3) = ue(6 * i - 5:6 * i - 3) - t - cross(w, d)
            ud(6 * i - 2:6 * i) = ue(6 * i - 2:6 * i) - w
        end do
    end subroutine remove_plate_rigid_motion

    pure function cross(a, b) result(c)
        real(dp), intent(in) :: a(3), b(3)
        real(dp) :: c(3)
        c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    end function cross

    !> Gathers the element displacements of a cell from u (absent equations: 0).
    pure function gather(u, eqs, n) result(ue)
        real(dp), intent(in) :: u(:)
        integer(i4), intent(in) :: eqs(:), n
        real(dp) :: ue(n)
        integer(i4) :: k
        do k = 1, n
            ue(k) = 0.0_dp
            if (eqs(k) > 0) ue(k) = u(eqs(k))
        end do
    end function gather

    !> gather as a subroutine: ue(1:n) = u(eqs(1:n)) (absent equations: 0).
    pure subroutine gather_into(u, eqs, n, ue)
        real(dp), intent(in) :: u(:)
        integer(i4), intent(in) :: eqs(:), n
        real(dp), intent(out) :: ue(:)
        integer(i4) :: k
        do k = 1, n
            ue(k) = 0.0_dp
            if (eqs(k) > 0) ue(k) = u(eqs(k))
        end do
    end subroutine gather_into

    !> (Re)allocates the element matrix and vector to n equations.
    subroutine size_element_arrays(n, ke, fe)
        integer(i4), intent(in) :: n
        real(dp), allocatable, intent(inout) :: ke(:, :), fe(:)
        if (allocated(fe)) then
            if (size(fe) == n) return
            deallocate (ke, fe)
        end if
        allocate (ke(n, n), fe(n))
    end subroutine size_element_arrays

    !> Assembles the stiffness of the free equations at displacements u.
    !>  elastic : in, .true. = every DIS_CHOC spring closed and bilateral (ELASTIQUE);
    !>            .false. = springs at the status u gives them (TANGENTE)
    !>  a       : inout, the matrix (pattern of map%pattern), zeroed and filled in place
    !>  st      : out, element failures, naming the cell
    !>  cache   : in, optional, once built (internal_forces_incremental): the plate and
    !>            plane matrices are taken from it (bit for bit those cell_response builds)
    !>  history : in, optional, DIS_CONTACT state at the start of the step
    subroutine assemble_stiffness(s, map, u, elastic, a, st, cache, history)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:)
        logical, intent(in) :: elastic
        type(sym_matrix_t), intent(inout) :: a
        type(status_t), intent(out) :: st
        type(linear_cache_t), intent(in), optional :: cache
        type(contact_history_t), intent(in), optional :: history
        integer(i4) :: k, c, n, eqs(MAX_ELEMENT_DOFS), i
        real(dp), allocatable :: ke(:, :), fe(:)
        real(dp) :: fn
        logical :: closed
        if (.not. allocated(a%col_ptr) .or. a%n /= map%n_free) a = map%pattern
        call sym_zero(a)
        do k = 1, size(map%cells)
            c = map%cells(k)
            call element_equations(s, c, eqs, n)
            call size_element_arrays(n, ke, fe)
            i = 0
            if (present(cache)) then
                if (cache%ready) i = cache%slot(k)
            end if
            if (i > 0) then
                call cached_global_matrix(cache, i, ke)
            else
                call cell_response(s, c, gather(u, eqs, n), n, elastic, .true., ke, fe, &
                    closed, fn, st, map, history)
                if (st%failed()) return
            end if
            if (map%reduced(k)) then
                call add_reduced_element(map, eqs(1:n), ke, a, st)
            else
                call sym_add_element(a, free_of(map, eqs(1:n)), ke, st)
            end if
            if (st%failed()) return
        end do
    end subroutine assemble_stiffness

    !> Adds an element matrix on equations with slaves: te^T ke te on the free equations
    !> the element depends on (assembly_relations).
    subroutine add_reduced_element(map, eqs, ke, a, st)
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(in) :: eqs(:)
        real(dp), intent(in) :: ke(:, :)
        type(sym_matrix_t), intent(inout) :: a
        type(status_t), intent(out) :: st
        integer(i4), allocatable :: red(:)
        real(dp), allocatable :: te(:, :), kred(:, :)
        integer(i4) :: m
        call element_transform(map%elim, map%free_eq, eqs, red, te, m)
        allocate (kred(m, m))
        call reduce_element(te, ke, kred)
        call sym_add_element(a, red, kred, st)
    end subroutine add_reduced_element

    !> Internal forces f_int(u) on every original equation, and the DIS_CHOC states.
    !>  fint   : out, (n_equations)
    !>  closed : out, (size(map%springs)) status of each DIS_CHOC spring
    !>  fn     : out, (size(map%springs)) normal force of each (<= 0 when closed)
    !>  history: in, optional, DIS_CONTACT state at the start of the step
    !>  u_body : in, optional, (n_equations) what the plates and plane solids see: u minus
    !>           the rigid modes the analysis keeps apart (their forces are zero, and
    !>           leaving them out keeps the round-off of the stiff bodies' forces off them)
    subroutine internal_forces(s, map, u, fint, closed, fn, st, history, u_body)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:)
        real(dp), intent(out) :: fint(:), fn(:)
        logical, intent(out) :: closed(:)
        type(status_t), intent(out) :: st
        type(contact_history_t), intent(in), optional :: history
        real(dp), intent(in), optional :: u_body(:)
        integer(i4) :: k, c, n, j, i_spring, eqs(MAX_ELEMENT_DOFS)
        real(dp), allocatable :: ke(:, :), fe(:)
        real(dp) :: f
        logical :: is_closed, body
        fint = 0.0_dp
        i_spring = 0
        do k = 1, size(map%cells)
            c = map%cells(k)
            call element_equations(s, c, eqs, n)
            call size_element_arrays(n, ke, fe)
            body = .false.
            if (present(u_body)) body = is_body_cell(s, c)
            if (body) then
                call cell_response(s, c, gather(u_body, eqs, n), n, .false., .false., ke, &
                    fe, is_closed, f, st, map, history)
            else
                call cell_response(s, c, gather(u, eqs, n), n, .false., .false., ke, fe, &
                    is_closed, f, st, map, history)
            end if
            if (st%failed()) return
            do j = 1, n
                if (eqs(j) > 0) fint(eqs(j)) = fint(eqs(j)) + fe(j)
            end do
            if (s%choc(c) .and. is_discrete(s%model%element(c))) then
                i_spring = i_spring + 1
                closed(i_spring) = is_closed
                fn(i_spring) = f
            end if
        end do
    end subroutine internal_forces

    !> Internal forces with the linear elements accumulated from increments:
    !> f_lin <- f_lin + K_lin du (plates and plane solids, K_lin constant), then
    !> f_int = f_lin + f_springs(u). The round-off of K_lin du scales with |du| (the
    !> Newton correction, or the imposed-value increment), not with |u|, so the computed
    !> residual can fall far below eps |K_lin| |u| (doc/analysis.md, "Residual floor").
    !> Springs (DIS_T, DIS_CHOC: soft, and DIS_CHOC nonlinear) are evaluated at u.
    !>  u      : in, the displacements (after the increment)
    !>  du     : in, the increment that led to u (imposed and free equations)
    !>  flin   : inout, (n_equations) linear-element forces, K_lin u up to round-off
    !>  fint   : out, (n_equations) flin + spring forces
    !>  closed, fn, st : as internal_forces
    !>  cache  : inout, optional, the linear cells' matrices (built on the first call that
    !>           passes it, then reused: the structure and map must stay the same)
    !>  history: in, optional, DIS_CONTACT state at the start of the step
    !>  u_ref, elastic_ref : in, optional (together): the contact springs are linearised
    !>           about u_ref, f(u_ref) + K (u - u_ref), K their elastic (elastic_ref) or
    !>           tangent matrix at u_ref, and closed/fn are their state at u_ref. This is
    !>           the force of Code_Aster's prediction with imposed-value increments (the
    !>           second member of nsassp: the increments enter through the matrix).
    !>  du_body: in, optional, (n_equations) the increment the plates and plane solids see:
    !>           du minus the rigid modes the analysis keeps apart (K_lin R = 0; leaving
    !>           them out keeps their round-off off f_lin)
    subroutine internal_forces_incremental(s, map, u, du, flin, fint, closed, fn, st, cache, &
                                           u_ref, elastic_ref, history, du_body)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:), du(:)
        real(dp), intent(inout) :: flin(:)
        real(dp), intent(out) :: fint(:), fn(:)
        logical, intent(out) :: closed(:)
        type(status_t), intent(out) :: st
        type(linear_cache_t), intent(inout), optional :: cache
        real(dp), intent(in), optional :: u_ref(:)
        logical, intent(in), optional :: elastic_ref
        type(contact_history_t), intent(in), optional :: history
        real(dp), intent(in), optional :: du_body(:)
        integer(i4) :: k, c, n, j, i_spring, eqs(MAX_ELEMENT_DOFS)
        real(dp), allocatable :: ke(:, :), fe(:)
        real(dp) :: ue(MAX_ELEMENT_DOFS), ur(MAX_ELEMENT_DOFS)
        real(dp) :: f
        logical :: is_closed, linear, linearise
        i_spring = 0
        if (present(cache)) then
            if (.not. cache%ready) call build_linear_cache(s, map, cache, st)
            if (st%failed()) return
            if (present(du_body)) then
                call add_cached_linear_forces(cache, du_body, flin)
            else
                call add_cached_linear_forces(cache, du, flin)
            end if
        else
            do k = 1, size(map%cells)
                c = map%cells(k)
                linear = is_plate(s%model%element(c)) .or. is_plane_solid(s%model%element(c))
                if (.not. linear) cycle
                call element_equations(s, c, eqs, n)
                call size_element_arrays(n, ke, fe)
                if (present(du_body)) then
                    call cell_response(s, c, gather(du_body, eqs, n), n, .false., .false., &
                        ke, fe, is_closed, f, st)
                else
                    call cell_response(s, c, gather(du, eqs, n), n, .false., .false., ke, &
                        fe, is_closed, f, st)
                end if
                if (st%failed()) return
                do j = 1, n
                    if (eqs(j) > 0) flin(eqs(j)) = flin(eqs(j)) + fe(j)
                end do
            end do
        end if
        fint = flin
        do k = 1, size(map%cells)
            c = map%cells(k)
            linear = is_plate(s%model%element(c)) .or. is_plane_solid(s%model%element(c))
            if (linear) cycle
            call element_equations(s, c, eqs, n)
            call size_element_arrays(n, ke, fe)
            call gather_into(u, eqs, n, ue)     ! a local array: no function-result temporary
            linearise = .false.
            if (present(u_ref)) linearise = s%choc(c)
            if (linearise) then
                call gather_into(u_ref, eqs, n, ur)
                call cell_response(s, c, ur(1:n), n, elastic_ref, .true., ke, fe, is_closed, &
                    f, st, map, history)
                if (st%ok()) fe = fe + matmul(ke, ue(1:n) - ur(1:n))
            else
                call cell_response(s, c, ue(1:n), n, .false., .false., ke, fe, is_closed, f, &
                    st, map, history)
            end if
            if (st%failed()) return
            do j = 1, n
                if (eqs(j) > 0) fint(eqs(j)) = fint(eqs(j)) + fe(j)
            end do
            if (s%choc(c) .and. is_discrete(s%model%element(c))) then
                i_spring = i_spring + 1
                closed(i_spring) = is_closed
                fn(i_spring) = f
            end if
        end do
    end subroutine internal_forces_incremental

    !> The closed (bilateral) matrix of every DIS_CHOC spring on its free equations, in
    !> map%springs order: the terms by which the tangents of two contact statuses differ
    !> (a closed spring's matrix does not depend on u).
    !>  sizes : out, (n_springs) equations of each spring's element (<= MAX_SPRING_DOFS)
    !>  eqs   : out, (MAX_SPRING_DOFS, n_springs) their free numbers, 0 = imposed
    !>  k     : out, (MAX_SPRING_DOFS, MAX_SPRING_DOFS, n_springs) the element matrices
    !>  st    : out, element failures, naming the cell
    subroutine spring_matrices(s, map, sizes, eqs, k, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4), intent(out) :: sizes(:), eqs(:, :)
        real(dp), intent(out) :: k(:, :, :)
        type(status_t), intent(out) :: st
        integer(i4) :: i, c, n, m, all_eqs(MAX_ELEMENT_DOFS)
        integer(i4), allocatable :: red(:)
        real(dp), allocatable :: ke(:, :), fe(:), te(:, :), kred(:, :)
        real(dp) :: fn
        logical :: closed
        eqs = 0
        k = 0.0_dp
        do i = 1, size(map%springs)
            c = map%springs(i)
            call element_equations(s, c, all_eqs, n)
            call size_element_arrays(n, ke, fe)
            call cell_response(s, c, spread(0.0_dp, 1, n), n, .true., .true., ke, fe, &
                closed, fn, st)
            if (st%failed()) return
            if (allocated(kred)) deallocate (kred)
            if (touches_slave(map%elim, all_eqs(1:n))) then
                ! a spring on a slave node: its matrix on the free equations it acts on
                call element_transform(map%elim, map%free_eq, all_eqs(1:n), red, te, m)
                allocate (kred(m, m))
                call reduce_element(te, ke, kred)
            else
                m = n
                if (allocated(red)) deallocate (red)
                allocate (red(n), kred(n, n))
                red(1:n) = free_of(map, all_eqs(1:n))
                kred(1:n, 1:n) = ke(1:n, 1:n)
            end if
            if (m > size(eqs, 1)) then
                call set_error(st, STATUS_MODEL_ERROR, cell_label(s%mesh, c) // ': ' // &
                    to_text(m) // ' equations, more than a spring''s ' // to_text(size(eqs, 1)))
                return
            end if
            sizes(i) = m
            eqs(1:m, i) = red
            k(1:m, 1:m, i) = kred
        end do
    end subroutine spring_matrices

    !> The most equations a spring's closed matrix acts on (spring_matrices): the spring's
    !> own, or with linear relations the free equations its slave equations depend on.
    integer(i4) function spring_block_width(s, map) result(width)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        integer(i4) :: i, n, m, all_eqs(MAX_ELEMENT_DOFS)
        integer(i4), allocatable :: red(:)
        real(dp), allocatable :: te(:, :)
        width = 0
        do i = 1, size(map%springs)
            call element_equations(s, map%springs(i), all_eqs, n)
            m = n
            if (touches_slave(map%elim, all_eqs(1:n))) &
                call element_transform(map%elim, map%free_eq, all_eqs(1:n), red, te, m)
            width = max(width, m)
        end do
    end function spring_block_width

    !> The energy of every DIS_CHOC spring along u + alpha du (choc_line_t), in
    !> map%springs order: what a line search on the contact energy needs.
    !>  u, du : in, (n_equations) displacements and direction (imposed equations of du: 0)
    !>  scale : in, > 0, the length unit of the lines (dis_choc_line_seg2)
    !>  lines : out, (n_springs)
    !>  st    : out, element failures, naming the cell
    subroutine spring_lines(s, map, u, du, scale, lines, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:), du(:), scale
        type(choc_line_t), intent(out) :: lines(:)
        type(status_t), intent(out) :: st
        integer(i4) :: i, c, n, m, eqs(MAX_ELEMENT_DOFS), p0
        real(dp) :: ue(MAX_ELEMENT_DOFS), de(MAX_ELEMENT_DOFS), x(3, 4)
        real(dp) :: k6(6, 6), k4(4, 4), k3(3, 3), k2(2, 2), c3(3, 2), c2(2, 2)
        do i = 1, size(map%springs)
            c = map%springs(i)
            call element_equations(s, c, eqs, n)
            call gather_into(u, eqs, n, ue)
            call gather_into(du, eqs, n, de)
            p0 = s%mesh%cell_ptr(c)
            x = 0.0_dp
            x(:, 1:2) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + 1))
            c3 = x(:, 1:2)
            c2 = x(1:2, 1:2)
            if (n == 6) then
                call discrete_matrix(s, c, x, n, k6, st)
                k3 = k6(1:3, 1:3)
            else
                call discrete_matrix(s, c, x, n, k4, st)
                k2 = k4(1:2, 1:2)
            end if
            if (st%failed()) then
                call set_error(st, st%code, cell_label(s%mesh, c) // ': ' // st%message)
                return
            end if
            m = material_of_cell(s%materials, c)
            associate (dc => s%materials%materials(m)%dis_contact)
                if (n == 6 .and. dc%has_rigi_nor) then
                    call dis_choc_line_seg2(3_i4, c3, ue(1:6), de(1:6), k3, dc%dist_1, &
                        dc%dist_2, scale, lines(i), dc%rigi_nor, dc%rigi_tan)
                else if (n == 6) then
                    call dis_choc_line_seg2(3_i4, c3, ue(1:6), de(1:6), k3, dc%dist_1, &
                        dc%dist_2, scale, lines(i), rigi_tan=dc%rigi_tan)
                else if (dc%has_rigi_nor) then
                    call dis_choc_line_seg2(2_i4, c2, ue(1:4), de(1:4), k2, dc%dist_1, &
                        dc%dist_2, scale, lines(i), dc%rigi_nor, dc%rigi_tan)
                else
                    call dis_choc_line_seg2(2_i4, c2, ue(1:4), de(1:4), k2, dc%dist_1, &
                        dc%dist_2, scale, lines(i), rigi_tan=dc%rigi_tan)
                end if
            end associate
        end do
    end subroutine spring_lines

    !> The product of the stiffness of every cell but the DIS_CHOC springs with du,
    !> computed element by element as the incremental forces are (plates and plane solids
    !> from the cache with each cell's rigid motion removed first, linear springs from
    !> their matrices): its round-off scales with each element's deformation, not with
    !> |K| |du| as an assembled product's does, which on a plate ~1e12 times stiffer than
    !> its springs would swamp the residuals the Newton iteration converges to.
    !>  cache : inout, the linear cells' matrices (built on the first call if needed)
    !>  du    : in, (n_equations); f : out, (n_equations)
    !>  st    : out, element failures, naming the cell
    !>  support_only : in, optional, .true.: leave the plates and plane solids (the cached
    !>          cells, body_product) out
    subroutine linear_product(s, map, cache, du, f, st, support_only)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(linear_cache_t), intent(inout) :: cache
        real(dp), intent(in) :: du(:)
        real(dp), intent(out) :: f(:)
        type(status_t), intent(out) :: st
        logical, intent(in), optional :: support_only
        integer(i4) :: k, c, n, j, eqs(MAX_ELEMENT_DOFS)
        real(dp), allocatable :: ke(:, :), fe(:)
        real(dp) :: ue(MAX_ELEMENT_DOFS), fn
        logical :: closed, body
        if (.not. cache%ready) call build_linear_cache(s, map, cache, st)
        if (st%failed()) return
        f = 0.0_dp
        body = .true.
        if (present(support_only)) body = .not. support_only
        if (body) call add_cached_linear_forces(cache, du, f)
        do k = 1, size(map%cells)
            c = map%cells(k)
            if (cache%slot(k) > 0 .or. s%choc(c)) cycle
            call element_equations(s, c, eqs, n)
            call size_element_arrays(n, ke, fe)
            call gather_into(du, eqs, n, ue)
            call cell_response(s, c, ue(1:n), n, .false., .false., ke, fe, closed, fn, st)
            if (st%failed()) return
            do j = 1, n
                if (eqs(j) > 0) f(eqs(j)) = f(eqs(j)) + fe(j)
            end do
        end do
    end subroutine linear_product

    !> f = K_b du: the product of the plates and plane solids (the bodies' cells, cached)
    !> with du, element by element with each cell's rigid motion removed first (as the
    !> incremental forces).
    !>  du, f : (n_equations)
    !>  st    : out, element failures while the cache is built, naming the cell
    subroutine body_product(s, map, cache, du, f, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(linear_cache_t), intent(inout) :: cache
        real(dp), intent(in) :: du(:)
        real(dp), intent(out) :: f(:)
        type(status_t), intent(out) :: st
        if (.not. cache%ready) call build_linear_cache(s, map, cache, st)
        if (st%failed()) return
        f = 0.0_dp
        call add_cached_linear_forces(cache, du, f)
    end subroutine body_product

    !> y = K_s x for several vectors on the free equations: K_s the stiffness of every cell
    !> but the plates and plane solids (springs, discrete elements), as assemble_stiffness
    !> builds it at u (elastic or at the springs' status there). What the rigid modes of
    !> spring-held bodies need (K_s R): the bodies' own cells give K_b R = 0.
    !>  u       : in, (n_equations) the displacements the matrix is assembled at
    !>  elastic : in, as assemble_stiffness
    !>  x       : in, (n_free, m); y : out, (n_free, m)
    !>  st      : out, element failures, naming the cell
    !>  history : in, optional, DIS_CONTACT state at the start of the step
    subroutine support_product(s, map, u, elastic, x, y, st, history)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: u(:), x(:, :)
        logical, intent(in) :: elastic
        real(dp), intent(out) :: y(:, :)
        type(status_t), intent(out) :: st
        type(contact_history_t), intent(in), optional :: history
        integer(i4) :: k, c, n, i, j, col, eqs(MAX_ELEMENT_DOFS), free(MAX_ELEMENT_DOFS)
        real(dp), allocatable :: ke(:, :), fe(:), v(:, :), f(:, :)
        real(dp) :: fn
        logical :: closed, relations
        ! with linear relations T^T K_s T x: the products on the original equations
        relations = has_relations(map%elim)
        if (relations) then
            allocate (v(s%dofs%n_equations, size(x, 2)), f(s%dofs%n_equations, size(x, 2)))
            do col = 1, size(x, 2, kind=i4)
                call scatter_free(map, x(:, col), v(:, col))
            end do
            f = 0.0_dp
        end if
        y = 0.0_dp
        do k = 1, size(map%cells)
            c = map%cells(k)
            if (is_body_cell(s, c)) cycle
            call element_equations(s, c, eqs, n)
            call size_element_arrays(n, ke, fe)
            call cell_response(s, c, gather(u, eqs, n), n, elastic, .true., ke, fe, closed, &
                fn, st, map, history)
            if (st%failed()) return
            if (relations) then
                do i = 1, n
                    if (eqs(i) == 0) cycle
                    do j = 1, n
                        if (eqs(j) > 0) f(eqs(i), :) = f(eqs(i), :) + ke(i, j) * v(eqs(j), :)
                    end do
                end do
                cycle
            end if
            free(1:n) = free_of(map, eqs(1:n))
            do i = 1, n
                if (free(i) == 0) cycle
                do j = 1, n
                    if (free(j) > 0) y(free(i), :) = y(free(i), :) + ke(i, j) * x(free(j), :)
                end do
            end do
        end do
        if (relations) then
            do col = 1, size(x, 2, kind=i4)
                call gather_free(map, f(:, col), y(:, col))
            end do
        end if
    end subroutine support_product

    !> Plates and plane solids: the cells whose rigid motions have zero energy (the bodies
    !> of analysis rigid_bodies; the linear cells of the cache).
    pure logical function is_body_cell(s, c)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        is_body_cell = is_plate(s%model%element(c)) .or. is_plane_solid(s%model%element(c))
    end function is_body_cell

    !> Computes the linear cells' data of `cache` (see linear_cache_t), in map%cells order.
    !>  st : out, element failures (material, geometry), naming the cell
    subroutine build_linear_cache(s, map, cache, st)
        type(structure_t), intent(in) :: s
        type(assembly_map_t), intent(in) :: map
        type(linear_cache_t), intent(inout) :: cache
        type(status_t), intent(out) :: st
        integer(i4) :: k, c, i, nc, nn, p0
        logical :: linear(size(map%cells))
        do k = 1, size(map%cells)
            c = map%cells(k)
            linear(k) = is_plate(s%model%element(c)) .or. is_plane_solid(s%model%element(c))
        end do
        nc = count(linear, kind=i4)
        allocate (cache%n(nc), cache%nn(nc), cache%plate(nc), cache%k_ptr(nc + 1), &
            cache%eqs(MAX_ELEMENT_DOFS, nc))
        allocate (cache%x(3, MAX_CELL_NODES, nc), cache%rot(3, 3, nc), cache%xy(2, 4, nc), &
            source=0.0_dp)
        i = 0
        cache%k_ptr(1) = 1
        do k = 1, size(map%cells)
            if (.not. linear(k)) cycle
            i = i + 1
            c = map%cells(k)
            call element_equations(s, c, cache%eqs(:, i), cache%n(i))
            cache%plate(i) = is_plate(s%model%element(c))
            p0 = s%mesh%cell_ptr(c)
            nn = s%mesh%cell_ptr(c + 1) - p0
            cache%nn(i) = nn
            cache%x(:, 1:nn, i) = s%mesh%coords(:, s%mesh%cell_nodes(p0:p0 + nn - 1))
            if (cache%plate(i)) then
                cache%k_ptr(i + 1) = cache%k_ptr(i) + plate_block_size(nn, &
                    plate_cell_coupled(s, c))
            else
                cache%k_ptr(i + 1) = cache%k_ptr(i) + int(cache%n(i), i8)**2
            end if
        end do
        allocate (cache%k(cache%k_ptr(nc + 1) - 1), cache%slot(size(map%cells)))
        call advise_huge_pages(cache%k)
        cache%slot = 0
        i = 0
        do k = 1, size(map%cells)
            if (.not. linear(k)) cycle
            i = i + 1
            cache%slot(k) = i
            call cache_cell_matrix(s, map%cells(k), cache, i, st)
            if (st%failed()) then
                call set_error(st, st%code, cell_label(s%mesh, map%cells(k)) // ': ' // &
                    st%message)
                return
            end if
        end do
        cache%ready = .true.
    end subroutine build_linear_cache

    !> Element matrix of cached cell i (mesh cell c): plates keep their local frame and
    !> local matrix (plate_internal_forces works in the local frame), plane solids the
    !> global matrix (as cell_response).
    subroutine cache_cell_matrix(s, c, cache, i, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c, i
        type(linear_cache_t), intent(inout) :: cache
        type(status_t), intent(out) :: st
        integer(i4) :: nn
        integer(i8) :: p, q
        real(dp) :: x2(2, MAX_CELL_NODES), kp(2 * MAX_CELL_NODES, 2 * MAX_CELL_NODES)
        type(plate_section_t) :: sec
        type(plane_law_t) :: law
        nn = cache%nn(i)
        p = cache%k_ptr(i)
        q = cache%k_ptr(i + 1) - 1
        if (cache%plate(i)) then
            call plate_local_frame(cache%x(:, 1:nn, i), nn, cache%rot(:, :, i), &
                cache%xy(:, 1:nn, i), st)
            if (st%ok()) call plate_cell_section(s%mesh, s%materials, s%cara, c, &
                cache%rot(:, :, i), sec, st)
            if (st%failed()) return
            if (sec%isotropic .and. .not. sec%coupled) then
                call plate_local_blocks(cache%xy(:, 1:nn, i), nn, sec%young, sec%nu, &
                    sec%thickness, s%cara%coef_rigi_drz(c), cache%k(p:q), st)
            else
                call plate_section_blocks(cache%xy(:, 1:nn, i), nn, sec%dm, sec%dmf, &
                    sec%df, s%cara%coef_rigi_drz(c), cache%k(p:q), st)
            end if
        else
            x2(:, 1:nn) = cache%x(1:2, 1:nn, i)    ! contiguous copy: no array temporary
            call plane_cell_law(s%mesh, s%model, s%materials, s%cara, c, law, st)
            if (st%ok()) call plane_stiffness(s%mesh%cell_type(c), x2(:, 1:nn), law%d3, &
                kp(1:2 * nn, 1:2 * nn), st)
            cache%k(p:q) = reshape(kp(1:2 * nn, 1:2 * nn), [4 * nn * nn])
        end if
    end subroutine cache_cell_matrix

    !> flin <- flin + K_lin du from the cached matrices, cell by cell in the order of
    !> map%cells, with the rigid motion of each cell removed first (as cell_response).
    subroutine add_cached_linear_forces(cache, du, flin)
        type(linear_cache_t), intent(in) :: cache
        real(dp), intent(in) :: du(:)
        real(dp), intent(inout) :: flin(:)
        integer(i4) :: i, j, n, nn
        integer(i8) :: p, q
        real(dp) :: fe(MAX_ELEMENT_DOFS), ue(MAX_ELEMENT_DOFS), ud(MAX_ELEMENT_DOFS)
        real(dp) :: x2(2, MAX_CELL_NODES)
        do i = 1, size(cache%n)
            n = cache%n(i)
            nn = cache%nn(i)
            p = cache%k_ptr(i)
            q = cache%k_ptr(i + 1) - 1
            do j = 1, n
                ue(j) = 0.0_dp
                if (cache%eqs(j, i) > 0) ue(j) = du(cache%eqs(j, i))
            end do
            if (cache%plate(i)) then
                call remove_plate_rigid_motion(cache%x(:, 1:nn, i), nn, ue(1:n), ud(1:n))
                call plate_forces_from_blocks(cache%rot(:, :, i), cache%xy(:, 1:nn, i), nn, &
                    cache%k(p:q), ud(1:n), fe(1:n))
            else
                x2(:, 1:nn) = cache%x(1:2, 1:nn, i)
                call plane_forces(cache%k(p:q), x2(:, 1:nn), nn, ue(1:n), fe(1:n))
            end if
            do j = 1, n
                if (cache%eqs(j, i) > 0) flin(cache%eqs(j, i)) = flin(cache%eqs(j, i)) + fe(j)
            end do
        end do
    end subroutine add_cached_linear_forces

    !> Global matrix of cached cell i, as plate_stiffness / plane_stiffness give it.
    subroutine cached_global_matrix(cache, i, ke)
        type(linear_cache_t), intent(in) :: cache
        integer(i4), intent(in) :: i
        real(dp), intent(out) :: ke(:, :)
        integer(i8) :: p, q
        real(dp) :: k24(24, 24), k18(18, 18)     ! contiguous: no array temporaries
        p = cache%k_ptr(i)
        q = cache%k_ptr(i + 1) - 1
        if (cache%plate(i) .and. cache%nn(i) == 4) then
            call expand_plate_blocks(4_i4, cache%k(p:q), k24)
            call rotate_to_global(cache%rot(:, :, i), 8_i4, k24, ke)
        else if (cache%plate(i)) then
            call expand_plate_blocks(3_i4, cache%k(p:q), k18)
            call rotate_to_global(cache%rot(:, :, i), 6_i4, k18, ke)
        else
            ke = reshape(cache%k(p:q), [cache%n(i), cache%n(i)])
        end if
    end subroutine cached_global_matrix

    !> Plane forces K u of the deformation part of ue (see remove_plane_rigid_motion).
    pure subroutine plane_forces(k, x2, nn, ue, fe)
        integer(i4), intent(in) :: nn
        real(dp), intent(in) :: k(2 * nn, 2 * nn), x2(2, nn), ue(2 * nn)
        real(dp), intent(out) :: fe(2 * nn)
        real(dp) :: ud(2 * nn)
        call remove_plane_rigid_motion(x2, nn, ue, ud)    ! not inline in matmul
        fe = matmul(k, ud)
    end subroutine plane_forces

    !> The response of one SEG2 spring (DIS_T, 2D_DIS_T; DIS_CHOC or linear) at u: its
    !> element displacements and the force on its second node (global frame), for the
    !> spring results (analysis spring_results: SIEF_ELGA, VARI_ELGA).
    !>  c      : in, a SEG2 discrete cell
    !>  ue     : out, ue(1:n) the element displacements, node 1 then node 2
    !>  n      : out, 2 x the space dimension
    !>  force2 : out, force2(1:n/2) the force on node 2
    !>  closed, fn : out, the DIS_CHOC status and normal force (closed, 0 for a linear one)
    !>  st     : out, element failures, naming the cell
    subroutine spring_response(s, c, u, ue, n, force2, closed, fn, st)
        type(structure_t), intent(in) :: s
        integer(i4), intent(in) :: c
        real(dp), intent(in) :: u(:)
        real(dp), intent(out) :: ue(MAX_ELEMENT_DOFS), force2(3), fn
        integer(i4), intent(out) :: n
        logical, intent(out) :: closed
        type(status_t), intent(out) :: st
        integer(i4) :: eqs(MAX_ELEMENT_DOFS)
        real(dp), allocatable :: ke(:, :), fe(:)
        force2 = 0.0_dp
        ue = 0.0_dp
        call element_equations(s, c, eqs, n)
        call gather_into(u, eqs, n, ue)
        call size_element_arrays(n, ke, fe)
        call cell_response(s, c, ue(1:n), n, .false., .false., ke, fe, closed, fn, st)
        if (st%failed()) return
        force2(1:n / 2) = fe(n / 2 + 1:n)
    end subroutine spring_response

    !> x = T^T v: a vector on the original equations (forces, residuals) on the free ones;
    !> without relations x = v(free_to_eq) (assembly_relations reduce_to_free).
    !>  x : out, (n_free)
    pure subroutine gather_free(map, v, x)
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: v(:)
        real(dp), intent(out) :: x(:)
        call reduce_to_free(map%elim, map%free_eq, map%free_to_eq, v, x)
    end subroutine gather_free

    !> v = T x: free values on the original equations, the slaves from them, the imposed
    !> equations 0 (a correction or direction; assembly_relations expand_free).
    !>  v : out, (n_equations)
    pure subroutine scatter_free(map, x, v)
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: x(:)
        real(dp), intent(out) :: v(:)
        call expand_free(map%elim, map%free_eq, map%free_to_eq, x, v)
    end subroutine scatter_free

    !> max |T^T (f_ext - f_int)| over the free equations (0 when there is none): the
    !> residual of each free equation with the forces of the relations on the slaves taken
    !> out (Code_Aster's per-DOF residual with the multipliers that balance the slaves).
    pure real(dp) function free_residual_max(map, fint, fext) result(r)
        type(assembly_map_t), intent(in) :: map
        real(dp), intent(in) :: fint(:), fext(:)
        real(dp), allocatable :: x(:)
        r = 0.0_dp
        if (map%n_free == 0) return
        allocate (x(map%n_free))
        call reduce_to_free(map%elim, map%free_eq, map%free_to_eq, fext - fint, x)
        r = maxval(abs(x))
    end function free_residual_max

    ! Moves an elimination (its arrays) into the map's.
    subroutine move_elimination(from, to)
        type(elimination_t), intent(inout) :: from
        type(elimination_t), intent(out) :: to
        to%n_slaves = from%n_slaves
        call move_alloc(from%slave_of, to%slave_of)
        call move_alloc(from%in_relation, to%in_relation)
        if (allocated(from%slave_eq)) call move_alloc(from%slave_eq, to%slave_eq)
        if (allocated(from%ptr)) call move_alloc(from%ptr, to%ptr)
        if (allocated(from%term_eq)) call move_alloc(from%term_eq, to%term_eq)
        if (allocated(from%term_coef)) call move_alloc(from%term_coef, to%term_coef)
        if (allocated(from%rhs_ptr)) call move_alloc(from%rhs_ptr, to%rhs_ptr)
        if (allocated(from%rhs_row)) call move_alloc(from%rhs_row, to%rhs_row)
        if (allocated(from%rhs_coef)) call move_alloc(from%rhs_coef, to%rhs_coef)
        to%rows = from%rows
    end subroutine move_elimination

end module assembly_system
