!> AFFE_CHAR_MECA LIAISON_PROJ (Code_Aster U4.44.01, catalog affe_char_meca.py): the linear
!> relations of a correspondence built by PROJ_CHAMP(PROJECTION='NON') between two parts of
!> the model's own mesh. Each node of the target side (MAILLAGE_2 / MODELE_2's nodes that
!> PROJ_CHAMP projected) is tied to the nodes of its source cell by the cell's shape
!> functions at the node, one relation per component of DDL:
!>     u_c(slave) = sum_i N_i u_c(master node i).
!> TYPE='EXCENTREMENT' (plates in a 3D mesh, source cells TRIA3 / QUAD4 only) adds the
!> rigid lever arm of each master node's rotation:
!>     u(slave) = sum_i N_i (u_i + theta_i x (x_slave - x_i)).
!> As Code_Aster does:
!>  - both meshes of the projection must be the model's mesh (Code_Aster CHARGES7_11);
!>  - a master coefficient (or lever-arm term) of magnitude at most COEF_TOLERANCE is left
!>    out of the relation (Code_Aster's tolerance on the coefficients of a relation);
!>  - a slave node that is itself a node of its source cell would be tied to itself: it gets
!>    no relation, with an alarm (Code_Aster CHARGES7_13);
!>  - a component the slave or a master node lacks is an error (Code_Aster CHARGES7_14);
!>    EXCENTREMENT on a master node without DRX, DRY, DRZ too (CHARGES7_16).
!>
!> The correspondence concept lives in the post layer (projection_concept), below this one:
!> the composition root gives this module the procedure that reads it
!> (set_projection_resolver), as it gives MODI_MAILLAGE its field-support resolver.
module relation_proj
    use kinds, only: dp, i4
    use status, only: status_t, STATUS_MODEL_ERROR, STATUS_NOT_IMPLEMENTED, STATUS_INTERNAL
    use strings, only: string_t, to_text
    use deck_concept, only: concept_t
    use deck_command, only: keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, node_name, cell_name, CELL_TRIA3, CELL_QUAD4, &
        CELL_TYPE_NODES
    use mesh_command_support, only: warn_at
    use model_dof_numbering, only: COMPONENT_NAMES, DOF_DX, DOF_DY, DOF_DZ, DOF_DRX, &
        DOF_DRY, DOF_DRZ, component_index
    use model_concept, only: model_concept_t
    use model_loads, only: load_set_t, load_add_item, load_add_relation, &
        LOAD_RELATION
    use load_occurrences, only: locate_item
    implicit none
    private

    public :: node_links_t, links_of_f, set_projection_resolver, liaison_proj_item

    !> Coefficients of a relation of magnitude at most this are left out (Code_Aster's
    !> KINE_LIST_RELA coefMultTole, 1e-6).
    real(dp), parameter :: COEF_TOLERANCE = 1.0e-6_dp

    !> A correspondence as LIAISON_PROJ reads it: for every node of the target mesh, its
    !> source cell (0: not projected) and the weights of that cell's nodes.
    type :: node_links_t
        type(mesh_t), pointer :: source => null()   !< MAILLAGE_1 / MODELE_1's mesh
        type(mesh_t), pointer :: target => null()   !< MAILLAGE_2 / MODELE_2's mesh
        integer(i4), allocatable :: cell(:)         !< (target nodes) source cell, 0: none
        real(dp), allocatable :: weights(:, :)      !< (MAX_CELL_NODES, target nodes)
    end type node_links_t

    abstract interface
        !> The links of a correspondence concept (corresp_2_mailla).
        !>  st : out, an error (unlocated) when the concept is not a correspondence
        subroutine links_of_f(concept, links, st)
            import :: concept_t, node_links_t, status_t
            class(concept_t), pointer, intent(in) :: concept
            type(node_links_t), intent(out) :: links
            type(status_t), intent(out) :: st
        end subroutine links_of_f
    end interface
    procedure(links_of_f), pointer, save :: links_of => null()

contains

    !> Gives LIAISON_PROJ the reader of PROJ_CHAMP's correspondence (module header).
    subroutine set_projection_resolver(resolver)
        procedure(links_of_f) :: resolver
        links_of => resolver
    end subroutine set_projection_resolver

    !> One LIAISON_PROJ occurrence: its relations in a new RELATION item of `loads`.
    subroutine liaison_proj_item(ctx, occ, mc, loads, st)
        type(run_context_t), intent(inout) :: ctx
        type(keyword_set_t), intent(in) :: occ
        type(model_concept_t), intent(in) :: mc
        type(load_set_t), intent(inout) :: loads
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        type(node_links_t) :: links
        type(string_t), allocatable :: ddl(:)
        character(len=:), allocatable :: kind, label, why
        integer(i4), allocatable :: comps(:), masters(:), nodes(:), cs(:)
        real(dp), allocatable :: coefs(:)
        integer(i4) :: k, n, c, nn, m, i, index, n_self, first_self, n_rel
        logical :: eccentric
        call occ%get_concept('MATR_PROJECTION', p, st)
        if (st%failed()) return
        if (.not. associated(links_of)) then
            call occ%error_at('MATR_PROJECTION', 'no reader of PROJ_CHAMP correspondences ' // &
                'is wired in (composition root)', st, code=STATUS_INTERNAL)
            return
        end if
        call links_of(p, links, st)
        if (st%failed()) then
            why = st%message
            call occ%error_at('MATR_PROJECTION', why, st, code=STATUS_MODEL_ERROR)
            return
        end if
        if (.not. (associated(links%source, mc%mesh) .and. &
                   associated(links%target, mc%mesh))) then
            call occ%error_at('MATR_PROJECTION', 'the projection ' // p%name // ' was built ' // &
                'between other meshes than the model''s: LIAISON_PROJ ties nodes of the ' // &
                'model''s own mesh, so PROJ_CHAMP must take it as MAILLAGE_1 (MODELE_1) and ' // &
                'MAILLAGE_2 (MODELE_2) (Code_Aster CHARGES7_11)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        kind = 'IDENTITE'
        if (occ%has('TYPE')) call occ%get_text('TYPE', kind, st)
        if (st%ok()) call occ%get_texts('DDL', ddl, st)
        if (st%failed()) return
        eccentric = kind == 'EXCENTREMENT'
        if (eccentric .and. mc%mesh%dim /= 3) then
            call occ%error_at('TYPE', "TYPE='EXCENTREMENT' ties plates in a 3D mesh; this " // &
                'mesh is 2D (Code_Aster CHARGES7_15)', st, code=STATUS_MODEL_ERROR)
            return
        end if
        allocate (comps(size(ddl)))
        do k = 1, size(ddl)
            comps(k) = component_index(ddl(k)%s)
            if (comps(k) == 0) then
                call occ%error_at('DDL', ddl(k)%s // ' is not a displacement or rotation ' // &
                    'component of parasol''s elements (DX DY DZ DRX DRY DRZ)', st, &
                    code=STATUS_NOT_IMPLEMENTED)
                return
            end if
            if (any(comps(1:k - 1) == comps(k))) then
                call occ%error_at('DDL', ddl(k)%s // ' is given twice', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
        end do

        call load_add_item(loads, LOAD_RELATION, [integer(i4) ::], index, label)
        call locate_item(occ, loads, index)
        n_self = 0
        first_self = 0
        n_rel = 0
        do n = 1, size(links%cell, kind=i4)
            c = links%cell(n)
            if (c <= 0) cycle
            nn = CELL_TYPE_NODES(mc%mesh%cell_type(c))
            masters = mc%mesh%cell_nodes(mc%mesh%cell_ptr(c):mc%mesh%cell_ptr(c) + nn - 1)
            if (any(masters == n)) then
                n_self = n_self + 1
                if (first_self == 0) first_self = n
                cycle
            end if
            if (eccentric .and. all(mc%mesh%cell_type(c) /= [CELL_TRIA3, CELL_QUAD4])) then
                call occ%error_at('TYPE', "TYPE='EXCENTREMENT' ties to TRIA3 and QUAD4 " // &
                    'cells only; slave node ' // node_name(mc%mesh, n) // ' projects on ' // &
                    cell_name(mc%mesh, c) // ' (Code_Aster CHARGES7_12)', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            do m = 1, size(comps)
                allocate (nodes(0), cs(0), coefs(0))
                call add(n, comps(m), 1.0_dp, .true., st)
                do i = 1, nn
                    if (st%failed()) return
                    if (eccentric) then
                        call add(masters(i), comps(m), -links%weights(i, n), .false., st)
                        if (st%ok()) call lever(masters(i), comps(m), links%weights(i, n), &
                            mc%mesh%coords(:, n) - mc%mesh%coords(:, masters(i)), st)
                    else if (abs(links%weights(i, n)) > COEF_TOLERANCE) then
                        call add(masters(i), comps(m), -links%weights(i, n), .false., st)
                    end if
                end do
                if (st%failed()) return
                call load_add_relation(loads, index, nodes, cs, coefs, 0_i4, n)
                n_rel = n_rel + 1
                deallocate (nodes, cs, coefs)
            end do
        end do
        if (n_self > 0) call warn_at(ctx, occ, 'MATR_PROJECTION', to_text(n_self) // &
            ' slave node(s) (' // node_name(mc%mesh, first_self) // ' first) are nodes of ' // &
            'the source cell they project on: a relation would tie them to themselves, none ' // &
            'is written for them (Code_Aster CHARGES7_13)')
        if (n_rel == 0) call warn_at(ctx, occ, 'MATR_PROJECTION', 'the projection ties no ' // &
            'node: LIAISON_PROJ adds no relation')

    contains

        ! A term of the relation being built; exact zeros left out; a component the node
        ! lacks is an error (Code_Aster CHARGES7_14).
        subroutine add(node, comp, coef, slave, st)
            integer(i4), intent(in) :: node, comp
            real(dp), intent(in) :: coef
            logical, intent(in) :: slave
            type(status_t), intent(out) :: st
            if (.not. abs(coef) > 0.0_dp) return
            if (mc%dofs%equation(comp, node) <= 0) then
                call occ%error_at('DDL', trim(merge('slave ', 'master', slave)) // ' node ' // &
                    node_name(mc%mesh, node) // ' has no component ' // &
                    trim(COMPONENT_NAMES(comp)) // ' in the model: no element carries it, a ' // &
                    'relation cannot hold it (Code_Aster CHARGES7_14)', st, &
                    code=STATUS_MODEL_ERROR)
                return
            end if
            nodes = [nodes, node]
            cs = [cs, comp]
            coefs = [coefs, coef]
        end subroutine add

        ! EXCENTREMENT: the translation `comp` of N_i theta_i x r, r = x_slave - x_master
        ! (x: theta_y r_z - theta_z r_y, and cyclically), its terms on the master's rotations.
        subroutine lever(node, comp, w, r, st)
            integer(i4), intent(in) :: node, comp
            real(dp), intent(in) :: w, r(3)
            type(status_t), intent(out) :: st
            integer(i4) :: q
            do q = DOF_DRX, DOF_DRZ
                if (mc%dofs%equation(q, node) <= 0) then
                    call occ%error_at('TYPE', "TYPE='EXCENTREMENT': master node " // &
                        node_name(mc%mesh, node) // ' has no ' // trim(COMPONENT_NAMES(q)) // &
                        ' (every master node needs DRX, DRY, DRZ; Code_Aster CHARGES7_16)', &
                        st, code=STATUS_MODEL_ERROR)
                    return
                end if
            end do
            select case (comp)
            case (DOF_DX)
                call lever_term(node, DOF_DRY, w * r(3))
                call lever_term(node, DOF_DRZ, -w * r(2))
            case (DOF_DY)
                call lever_term(node, DOF_DRX, -w * r(3))
                call lever_term(node, DOF_DRZ, w * r(1))
            case (DOF_DZ)
                call lever_term(node, DOF_DRX, w * r(2))
                call lever_term(node, DOF_DRY, -w * r(1))
            end select
        end subroutine lever

        subroutine lever_term(node, comp, coef)
            integer(i4), intent(in) :: node, comp
            real(dp), intent(in) :: coef
            if (.not. abs(coef) > COEF_TOLERANCE) return
            nodes = [nodes, node]
            cs = [cs, comp]
            coefs = [coefs, -coef]
        end subroutine lever_term
    end subroutine liaison_proj_item

end module relation_proj
