!> CALC_CHAMP (Code_Aster U4.81.04, code_aster/Cata/Commands/calc_champ.py): computes
!> fields of a result at its stored instants and stores them in it (reuse=) or in a copy
!> (doc/fields.md, "CALC_CHAMP"). Options by keyword:
!>   CONTRAINTE  SIEF_ELGA (linear results), SIGM_ELGA, SIGM_ELNO, SIGM_NOEU, SIEF_ELNO,
!>               SIEF_NOEU, EFGE_ELGA, EFGE_ELNO, EFGE_NOEU
!>   DEFORMATION EPSI_ELGA, EPSI_ELNO, EPSI_NOEU, DEGE_ELGA, DEGE_ELNO, DEGE_NOEU,
!>               EPME_* and EPSP_* (plane elements: elem's element_fields)
!>   CRITERES    SIEQ_ELGA, SIEQ_ELNO, SIEQ_NOEU, EPEQ_ELGA, EPEQ_ELNO, EPEQ_NOEU
!>   ENERGIE     ENEL_ELGA, ENEL_ELNO, ENEL_NOEU, ENEL_ELEM, ETOT_ELGA, ETOT_ELNO,
!>               ETOT_NOEU, ETOT_ELEM (energy_fields)
!>   FORCE       FORC_NODA, REAC_NODA
!> on NUME_ORDRE / INST / LIST_INST / TOUT_ORDRE (default every instant) and TOUT /
!> GROUP_MA (default every cell). How each is made (Code_Aster's element catalogue,
!> te0004/te0033/ef0033/ef0031): element values at the Gauss points from the displacements
!> (element_fields, plate_options); *_ELNO extrapolated from *_ELGA (field_transforms),
!> except where Code_Aster evaluates at the nodes (a linear result's EFGE_ELNO of plates,
!> DEGE_ELNO); *_NOEU the mean over the cells around a node of *_ELNO; SIEQ/EPEQ from the
!> stresses/strains point by point. A field an option needs is taken as the result stores
!> it (a POST_CHAMP layer), else computed on the way (and not stored).
module calc_champ_command
    use keyword_relocation, only: relocate => relocate_error
    use kinds, only: dp, i4, i8
    use status, only: status_t, set_error, STATUS_MODEL_ERROR, &
        STATUS_NOT_IMPLEMENTED
    use strings, only: string_t, to_text
    use deck_value, only: append_string
    use deck_concept, only: concept_t
    use deck_command, only: command_t, keyword_set_t
    use run_context, only: run_context_t
    use mesh_types, only: mesh_t, find_cell_group, cells_of_group
    use model_types, only: is_discrete
    use real_list, only: real_list_t
    use field_types, only: field_t, component_set_t, field_init_cells, field_define_cells, &
        field_component, FIELD_ELGA, FIELD_ELNO, field_position
    use result_fields, only: result_fields_t, result_find, result_put_field, &
        result_field_index
    use analysis_result, only: result_concept_t
    use result_access, only: result_field_at
    use element_fields, only: plate_field, strain_field, STRAIN_MECHANICAL, STRAIN_INELASTIC
    use plate_options, only: PLATE_FORCES, PLATE_GENERAL, PLATE_FORCES_CMPS, &
        PLATE_GENERAL_CMPS
    use field_transforms, only: gauss_to_nodes, nodes_average, equivalent_field
    use energy_fields, only: energy_field
    implicit none
    private

    !> The options CALC_CHAMP computes, by keyword (module header).
    character(len=*), parameter, public :: CALC_CHAMP_BUILT = 'SIEF_ELGA SIGM_ELGA ' // &
        'SIGM_ELNO SIGM_NOEU SIEF_ELNO SIEF_NOEU EFGE_ELGA EFGE_ELNO EFGE_NOEU EPSI_ELGA ' // &
        'EPSI_ELNO EPSI_NOEU EPME_ELGA EPME_ELNO EPME_NOEU EPSP_ELGA EPSP_ELNO EPSP_NOEU ' // &
        'DEGE_ELGA DEGE_ELNO DEGE_NOEU SIEQ_ELGA SIEQ_ELNO SIEQ_NOEU ' // &
        'EPEQ_ELGA EPEQ_ELNO EPEQ_NOEU ENEL_ELGA ENEL_ELNO ENEL_NOEU ENEL_ELEM ETOT_ELGA ' // &
        'ETOT_ELNO ETOT_NOEU ETOT_ELEM FORC_NODA REAC_NODA'
    character(len=12), parameter :: FAMILIES(6) = ['CONTRAINTE  ', 'DEFORMATION ', &
        'ENERGIE     ', 'CRITERES    ', 'FORCE       ', 'VARI_INTERNE']

    !> What one computation works on.
    type :: job_t
        class(result_fields_t), pointer :: res => null()
        logical, allocatable :: cells(:)      !< the cells asked for (TOUT / GROUP_MA)
        logical :: linear = .true.            !< evol_elas (Code_Aster's 'lin' options)
    end type job_t

    public :: run_calc_champ, compute_field

contains

    !> Handler of CALC_CHAMP (doc/architecture.md "Writing a command handler"; registered
    !> with reuse: reuse=RESU computes into RESU in place, else into a copy of RESULTAT).
    !>  st : located errors: an instant not stored, an unknown group, an option not built
    !>       or not for this result, an element failure naming the cell
    subroutine run_calc_champ(ctx, cmd, result, st)
        type(run_context_t), intent(inout) :: ctx
        type(command_t), intent(in) :: cmd
        class(concept_t), allocatable, intent(out) :: result
        type(status_t), intent(out) :: st
        class(concept_t), pointer :: p
        class(result_fields_t), allocatable, target :: copy
        type(job_t) :: job
        type(string_t), allocatable :: options(:)
        integer(i4), allocatable :: indices(:)
        integer(i4) :: k, i
        integer(i8) :: start, finish, rate
        real(dp) :: cpu_start, cpu_finish
        call cmd%get_concept('RESULTAT', p, st)
        if (st%failed()) return
        select type (p)
        class is (result_fields_t)
            if (associated(cmd%reuse)) then
                job%res => p
            else
                allocate (copy, source=p)
                job%res => copy
            end if
        class default
            call cmd%error_at('RESULTAT', 'expected a result, got ' // p%type_name(), st)
            return
        end select
        call system_clock(start)
        call cpu_time(cpu_start)
        job%linear = job%res%type_name() /= 'evol_noli'
        call read_options(cmd, job, options, st)
        if (st%ok()) call read_instants(cmd, job%res, indices, st)
        if (st%ok()) call read_cells(cmd, job, st)
        if (st%failed()) return
        do i = 1, size(indices)
            do k = 1, size(options)
                call compute_field(job, indices(i), options(k)%s, st)
                if (st%failed()) then
                    st%message = options(k)%s // ' at NUME_ORDRE ' // &
                        to_text(job%res%nume_ordre(indices(i))) // ': ' // st%message
                    call relocate(cmd, option_keyword(cmd, options(k)%s), st)
                    return
                end if
            end do
        end do
        call system_clock(finish, rate)
        call cpu_time(cpu_finish)
        ! wall and CPU: benchmarks on a shared machine read the CPU (doc/performance.md)
        call ctx%write_mess('    CALC_CHAMP: ' // join(options) // ' at ' // &
            to_text(size(indices)) // ' instant(s), ' // seconds(finish - start, rate) // &
            ' s (CPU ' // seconds(nint((cpu_finish - cpu_start) * 1.0e6_dp, i8), &
            1000000_i8) // ' s)')
        if (allocated(copy)) call move_alloc(copy, result)
    end subroutine run_calc_champ

    ! Elapsed clock ticks as seconds with 3 decimals (for the .mess).
    function seconds(ticks, rate) result(text)
        integer(i8), intent(in) :: ticks, rate
        character(len=:), allocatable :: text
        character(len=32) :: buf
        write (buf, '(f0.3)') real(ticks, dp) / real(max(rate, 1_i8), dp)
        text = trim(buf)
        if (text(1:1) == '.') text = '0' // text
    end function seconds

    !> The options of CONTRAINTE, DEFORMATION, ENERGIE, CRITERES, FORCE, VARI_INTERNE in the
    !> order given; each must be built, and for the result's kind.
    subroutine read_options(cmd, job, options, st)
        type(command_t), intent(in) :: cmd
        type(job_t), intent(in) :: job
        type(string_t), allocatable, intent(out) :: options(:)
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:), all(:)
        integer :: f, j
        allocate (all(0))
        do f = 1, size(FAMILIES)
            if (.not. cmd%has(trim(FAMILIES(f)))) cycle
            call cmd%get_texts(trim(FAMILIES(f)), names, st)
            if (st%failed()) return
            do j = 1, size(names)
                if (index(' ' // CALC_CHAMP_BUILT // ' ', ' ' // names(j)%s // ' ') == 0) then
                    call cmd%error_at(trim(FAMILIES(f)), names(j)%s // ' is not built in ' // &
                        'parasol (CALC_CHAMP computes ' // CALC_CHAMP_BUILT // ')', st, &
                        STATUS_NOT_IMPLEMENTED)
                    return
                end if
                if (names(j)%s == 'SIEF_ELGA' .and. .not. job%linear) then
                    call cmd%error_at(trim(FAMILIES(f)), 'SIEF_ELGA of a non-linear result ' // &
                        'is its state of stress, stored by STAT_NON_LINE: it is not ' // &
                        'recomputed (Code_Aster''s catalogue: a linear option)', st, &
                        STATUS_MODEL_ERROR)
                    return
                end if
                call append_string(all, names(j)%s)
            end do
        end do
        if (size(all) == 0) then
            call cmd%error_at('RESULTAT', 'give the fields to compute (CONTRAINTE, ' // &
                'DEFORMATION, CRITERES, FORCE ...)', st, STATUS_MODEL_ERROR)
            return
        end if
        call move_alloc(all, options)
    end subroutine read_options

    !> The instants (indices into the result): TOUT_ORDRE / NUME_ORDRE / INST / LIST_INST,
    !> default every stored one.
    subroutine read_instants(cmd, res, indices, st)
        type(command_t), intent(in) :: cmd
        class(result_fields_t), intent(in) :: res
        integer(i4), allocatable, intent(out) :: indices(:)
        type(status_t), intent(out) :: st
        real(dp), allocatable :: times(:)
        integer(i4), allocatable :: numbers(:)
        real(dp) :: precision
        character(len=:), allocatable :: criterion, key
        class(concept_t), pointer :: p
        integer :: k
        precision = 1.0e-6_dp
        criterion = 'RELATIF'
        if (cmd%has('PRECISION')) call cmd%get_real('PRECISION', precision, st)
        if (st%ok() .and. cmd%has('CRITERE')) call cmd%get_text('CRITERE', criterion, st)
        if (st%failed()) return
        if (cmd%has('NUME_ORDRE')) then
            call cmd%get_ints('NUME_ORDRE', numbers, st)
            if (st%failed()) return
            allocate (indices(size(numbers)))
            do k = 1, size(numbers)
                call result_find(res, indices(k), st, nume_ordre=numbers(k))
                if (st%failed()) then
                    call relocate(cmd, 'NUME_ORDRE', st)
                    return
                end if
            end do
            return
        end if
        key = ''
        if (cmd%has('INST')) then
            key = 'INST'
            call cmd%get_reals('INST', times, st)
        else if (cmd%has('LIST_INST')) then
            key = 'LIST_INST'
            call cmd%get_concept('LIST_INST', p, st)
            if (st%ok()) then
                select type (p)
                type is (real_list_t)
                    times = p%values
                class default
                    call cmd%error_at('LIST_INST', 'expected a list of reals', st)
                end select
            end if
        end if
        if (st%failed()) return
        if (len(key) == 0) then
            indices = [(k, k = 1, res%n_stored)]
            return
        end if
        allocate (indices(size(times)))
        do k = 1, size(times)
            call result_find(res, indices(k), st, inst=times(k), precision=precision, &
                criterion=criterion)
            if (st%failed()) then
                call relocate(cmd, key, st)
                return
            end if
        end do
    end subroutine read_instants

    !> TOUT / GROUP_MA: the cells to compute on (every cell by default).
    subroutine read_cells(cmd, job, st)
        type(command_t), intent(in) :: cmd
        type(job_t), intent(inout) :: job
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        type(mesh_t), pointer :: mesh
        integer(i4) :: k, g
        mesh => null()
        select type (r => job%res)
        type is (result_concept_t)
            mesh => r%mesh
        end select
        if (.not. associated(mesh)) then
            call cmd%error_at('RESULTAT', 'the result knows no mesh', st, STATUS_MODEL_ERROR)
            return
        end if
        allocate (job%cells(mesh%n_cells), source=.not. cmd%has('GROUP_MA'))
        if (.not. cmd%has('GROUP_MA')) return
        call cmd%get_texts('GROUP_MA', names, st)
        if (st%failed()) return
        do k = 1, size(names)
            g = find_cell_group(mesh, names(k)%s, st)
            if (st%failed()) then
                call relocate(cmd, 'GROUP_MA', st)
                return
            end if
            job%cells(cells_of_group(mesh, g)) = .true.
        end do
    end subroutine read_cells

    !> Computes field `name` at stored instant `at` and stores it in the result.
    recursive subroutine compute_field(job, at, name, st)
        type(job_t), intent(inout) :: job
        integer(i4), intent(in) :: at
        character(len=*), intent(in) :: name
        type(status_t), intent(out) :: st
        type(field_t) :: made
        type(field_t), pointer :: source
        character(len=:), allocatable :: base
        select case (name)
        case ('SIEF_ELGA', 'FORC_NODA', 'REAC_NODA')
            call result_field_at(job%res, at, name, source, st)      ! from the state
            return
        end select
        select type (r => job%res)
        type is (result_concept_t)
            base = name(1:4)
            select case (name)
            case ('SIGM_ELGA')
                call input_field(job, at, 'SIEF_ELGA', source, st)
                if (st%ok()) call restrict_components(source, 'SIXX SIYY SIZZ SIXY SIXZ ' // &
                    'SIYZ', made, st)
            case ('SIGM_ELNO', 'SIEF_ELNO', 'EPSI_ELNO', 'EPME_ELNO', 'EPSP_ELNO', &
                  'ENEL_ELNO', 'ETOT_ELNO')
                call input_field(job, at, base // '_ELGA', source, st)
                if (st%ok()) call gauss_to_nodes(source, r%mesh, r%model, made, st)
            case ('ENEL_ELGA', 'ENEL_ELEM', 'ETOT_ELGA', 'ETOT_ELEM')
                call energy_field(r, at, name, job%cells, made, st)
            case ('EFGE_ELGA')
                call forces_field(job, r, at, FIELD_ELGA, made, st)
            case ('EFGE_ELNO')
                call forces_field(job, r, at, FIELD_ELNO, made, st)
            case ('DEGE_ELGA', 'DEGE_ELNO')
                call require_state(r, st)
                if (st%ok()) call plate_field(r, r%depl(:, at), PLATE_GENERAL, &
                    merge(FIELD_ELGA, FIELD_ELNO, name == 'DEGE_ELGA'), 'EPSI_R', &
                    PLATE_GENERAL_CMPS, made, st, job%cells)
            case ('EPSI_ELGA')
                call require_state(r, st)
                if (st%ok()) call strain_field(r, r%depl(:, at), made, st, job%cells, &
                    r%inst(at))
            case ('EPME_ELGA', 'EPSP_ELGA')     ! elem's: plane elements (element_fields)
                call require_state(r, st)
                if (st%ok()) call strain_field(r, r%depl(:, at), made, st, job%cells, &
                    r%inst(at), merge(STRAIN_MECHANICAL, STRAIN_INELASTIC, name == 'EPME_ELGA'))
            case ('SIEQ_ELGA', 'SIEQ_ELNO')
                call input_field(job, at, 'SIGM' // name(5:), source, st)
                if (st%ok()) call equivalent_field(source, 'SIGM', made, st)
            case ('EPEQ_ELGA', 'EPEQ_ELNO')
                call input_field(job, at, 'EPSI' // name(5:), source, st)
                if (st%ok()) call equivalent_field(source, 'EPSI', made, st)
            case default
                if (name(6:9) == 'NOEU') then
                    call input_field(job, at, base // '_ELNO', source, st)
                    if (st%ok()) call nodes_average(source, r%mesh, made, st)
                else
                    call set_error(st, STATUS_NOT_IMPLEMENTED, name // ' is not built')
                end if
            end select
        class default
            call set_error(st, STATUS_MODEL_ERROR, 'the result knows no mesh nor model ' // &
                'to compute on')
        end select
        if (st%failed()) return
        call result_put_field(job%res, at, name, made)
    end subroutine compute_field

    !> The field an option is computed from: stored in the result, else computed now.
    recursive subroutine input_field(job, at, name, f, st)
        type(job_t), intent(inout) :: job
        integer(i4), intent(in) :: at
        character(len=*), intent(in) :: name
        type(field_t), pointer, intent(out) :: f
        type(status_t), intent(out) :: st
        f => null()
        if (result_field_index(job%res, at, name) == 0) then
            select case (name)
            case ('SIEF_ELGA', 'FORC_NODA', 'REAC_NODA')
            case default
                call compute_field(job, at, name, st)
                if (st%failed()) return
            end select
        end if
        call result_field_at(job%res, at, name, f, st)
    end subroutine input_field

    !> EFGE_ELGA / EFGE_ELNO: plates' forces and moments (at the nodes of a linear result,
    !> else extrapolated), springs' forces (their SIEF_ELGA: their points are their nodes).
    recursive subroutine forces_field(job, r, at, location, f, st)
        type(job_t), intent(inout) :: job
        type(result_concept_t), intent(in) :: r
        integer(i4), intent(in) :: at, location
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(field_t) :: plates, gauss
        type(field_t), pointer :: sief
        logical :: any_spring
        call require_state(r, st)
        if (st%failed()) return
        if (location == FIELD_ELNO .and. .not. job%linear) then
            call plate_field(r, r%depl(:, at), PLATE_FORCES, FIELD_ELGA, 'SIEF_R', &
                PLATE_FORCES_CMPS, gauss, st, job%cells, inst=r%inst(at))
            if (st%ok()) call gauss_to_nodes(gauss, r%mesh, r%model, plates, st)
        else
            call plate_field(r, r%depl(:, at), PLATE_FORCES, location, 'SIEF_R', &
                PLATE_FORCES_CMPS, plates, st, job%cells, inst=r%inst(at))
        end if
        if (st%failed()) return
        any_spring = any(is_discrete(r%model%element) .and. job%cells)
        if (.not. any_spring) then
            call move_field_into(plates, f)
            return
        end if
        call input_field(job, at, 'SIEF_ELGA', sief, st)
        if (st%failed()) return
        call merge_springs(plates, sief, r, job%cells, location, f, st)
    end subroutine forces_field

    !> The plates' field completed with the springs' N VY VZ of SIEF_ELGA.
    subroutine merge_springs(plates, sief, r, cells, location, f, st)
        type(field_t), intent(in) :: plates, sief
        type(result_concept_t), intent(in) :: r
        logical, intent(in) :: cells(:)
        integer(i4), intent(in) :: location
        type(field_t), intent(out) :: f
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: names(:)
        type(component_set_t) :: sets(3)
        integer(i4), allocatable :: n_points(:), n_sub(:), cell_set(:)
        integer(i4) :: c, j, n, k
        integer(i4) :: spring_cmp(3)
        allocate (names(0))
        do j = 1, size(plates%components, kind=i4)
            call append_string(names, plates%components(j)%s)
        end do
        call append_string(names, 'N')
        call append_string(names, 'VY')
        call append_string(names, 'VZ')
        call field_init_cells(f, location, 'SIEF_R', names, r%mesh%n_cells, st)
        if (st%failed()) return
        n = size(plates%components, kind=i4)
        sets(1)%cmp = [(j, j = 1, n)]
        sets(2)%cmp = [n + 1, n + 2, n + 3]
        sets(3)%cmp = [n + 1, n + 2]
        do j = 1, 3
            spring_cmp(j) = field_component(sief, trim(names(n + j)%s))
        end do
        allocate (n_points(r%mesh%n_cells), n_sub(r%mesh%n_cells), cell_set(r%mesh%n_cells), &
            source=0_i4)
        do c = 1, r%mesh%n_cells
            if (plates%n_points(c) > 0) then
                n_points(c) = plates%n_points(c)
                n_sub(c) = plates%n_subpoints(c)
                cell_set(c) = 1
            else if (cells(c) .and. is_discrete(r%model%element(c)) .and. &
                     sief%n_points(c) > 0) then
                n_points(c) = sief%n_points(c)
                n_sub(c) = 1
                cell_set(c) = 2
                if (field_position(sief, c, 1_i4, 1_i4, spring_cmp(3)) == 0) cell_set(c) = 3
            end if
        end do
        call field_define_cells(f, n_points, n_sub, cell_set, sets, st)
        if (st%failed()) return
        do c = 1, r%mesh%n_cells
            if (cell_set(c) == 1) then
                f%values(f%offset(c) + 1:f%offset(c + 1)) = &
                    plates%values(plates%offset(c) + 1:plates%offset(c + 1))
            else if (cell_set(c) > 1) then
                do k = 1, n_points(c)
                    do j = 1, size(sets(cell_set(c))%cmp)
                        f%values(field_position(f, c, k, 1_i4, n + j)) = &
                            sief%values(field_position(sief, c, k, 1_i4, spring_cmp(j)))
                    end do
                end do
            end if
        end do
    end subroutine merge_springs

    !> A copy of `f` holding only the components `names` (cells without any left out).
    subroutine restrict_components(f, names, out, st)
        type(field_t), intent(in) :: f
        character(len=*), intent(in) :: names
        type(field_t), intent(out) :: out
        type(status_t), intent(out) :: st
        type(string_t), allocatable :: wanted(:), kept(:)
        integer(i4), allocatable :: n_points(:), cell_set(:), map(:)
        type(component_set_t), allocatable :: sets(:)
        integer(i4) :: c, j, s, p, q, n_in, n_out
        call split(names, wanted)
        allocate (map(size(f%components)), source=0_i4)
        allocate (kept(0))
        do j = 1, size(f%components)
            do q = 1, size(wanted, kind=i4)
                if (wanted(q)%s /= f%components(j)%s) cycle
                call append_string(kept, f%components(j)%s)
                map(j) = size(kept, kind=i4)
            end do
        end do
        call field_init_cells(out, f%location, f%quantity, kept, f%n_cells, st)
        if (st%failed()) return
        allocate (sets(size(f%sets)))
        do s = 1, size(f%sets)
            sets(s)%cmp = pack(map(f%sets(s)%cmp), map(f%sets(s)%cmp) > 0)
        end do
        n_points = f%n_points
        cell_set = f%cell_set
        do c = 1, f%n_cells
            if (n_points(c) == 0) cycle
            if (size(sets(cell_set(c))%cmp) == 0) n_points(c) = 0
        end do
        call field_define_cells(out, n_points, f%n_subpoints, cell_set, sets, st)
        if (st%failed()) return
        do c = 1, f%n_cells
            if (n_points(c) == 0) cycle
            n_in = size(f%sets(f%cell_set(c))%cmp, kind=i4)
            n_out = size(sets(cell_set(c))%cmp, kind=i4)
            do p = 1, n_points(c) * f%n_subpoints(c)
                q = 0
                do j = 1, n_in
                    if (map(f%sets(f%cell_set(c))%cmp(j)) == 0) cycle
                    q = q + 1
                    out%values(out%offset(c) + (p - 1) * n_out + q) = &
                        f%values(f%offset(c) + (p - 1) * n_in + j)
                end do
            end do
        end do
    end subroutine restrict_components

    !> The result must hold displacements (an analysis's).
    subroutine require_state(r, st)
        type(result_concept_t), intent(in) :: r
        type(status_t), intent(out) :: st
        if (.not. (r%has_state .and. r%has_structure)) call set_error(st, &
            STATUS_MODEL_ERROR, 'the result holds no displacement to compute from (a ' // &
            'result of MECA_STATIQUE or STAT_NON_LINE has one)')
    end subroutine require_state

    !> Moves a field's arrays (no copy).
    subroutine move_field_into(from, to)
        type(field_t), intent(inout) :: from
        type(field_t), intent(out) :: to
        to = from
    end subroutine move_field_into

    !> The family keyword that names an option (for errors).
    function option_keyword(cmd, name) result(key)
        type(command_t), intent(in) :: cmd
        character(len=*), intent(in) :: name
        character(len=:), allocatable :: key
        type(string_t), allocatable :: names(:)
        type(status_t) :: st
        integer :: f, j
        key = 'RESULTAT'
        do f = 1, size(FAMILIES)
            if (.not. cmd%has(trim(FAMILIES(f)))) cycle
            call cmd%get_texts(trim(FAMILIES(f)), names, st)
            do j = 1, size(names)
                if (names(j)%s == name) key = trim(FAMILIES(f))
            end do
        end do
    end function option_keyword

    pure function join(names) result(text)
        type(string_t), intent(in) :: names(:)
        character(len=:), allocatable :: text
        integer :: k
        text = ''
        do k = 1, size(names)
            if (k > 1) text = text // ' '
            text = text // names(k)%s
        end do
    end function join

    subroutine split(text, words)
        use deck_catalog, only: split_words
        character(len=*), intent(in) :: text
        type(string_t), allocatable, intent(out) :: words(:)
        call split_words(text, words)
    end subroutine split

end module calc_champ_command
